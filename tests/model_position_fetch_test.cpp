// vertex_position<i> (gl_HitTriangleVertexPositionsEXT, R-POSITION-FETCH):
// the model gives the hit triangle's object-space vertices in the order the
// geometry lists them, through its geometry transform and not the instance
// transform (tests/glsl_position_fetch_test.cpp: its GLSL); a group with an intersection shader may
// not read it.
#include "model_support.h"

namespace rayspec::model_test {
namespace {

std::string caseText(const std::string& geometry_transform, const std::string& group_extra = "") {
  return "rules: [R-POSITION-FETCH]\n"
         "scene:\n"
         "  blas:\n"
         "    quad:\n"
         "      - triangles:\n"
         "          vertices: [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]\n"
         "          indices: [0, 1, 2, 0, 2, 3]\n"
         "        transform: " +
         geometry_transform +
         "\n"
         "        flags: [opaque]\n"
         "  instances:\n"
         "    - {blas: quad, transform: {translate: [10, 0, 0], scale: 2}}\n"
         "rays:\n"
         "  list:\n"
         "    - {origin: [11, -0.5, 5], direction: [0, 0, -1]}\n"
         "    - {origin: [9, 0.5, 5], direction: [0, 0, -1]}\n"
         "pipeline:\n"
         "  hit_groups:\n"
         "    - closest_hit: [record: {hit_position: vertex_position2, color: {vec4: [{x: "
         "vertex_position0}, {y: vertex_position0}, {x: vertex_position1}, {y: "
         "vertex_position1}]}}]\n" +
         group_extra +
         "outputs:\n"
         "  per_ray: [hit_position, color]\n";
}

const std::string kIdentityRows = "[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0]";

TEST(PositionFetch, ObjectSpaceVerticesInTheGeometrysOrder) {
  const Case c = parseInline(caseText(kIdentityRows));
  const Results r = runTier(c, ModelTier::Exact);
  // Ray 0 (world 11, -0.5: object 0.5, -0.25) is in triangle 0 (0, 1, 2).
  EXPECT_EQ(fword(r, 0, "color", 0), -1.0f);
  EXPECT_EQ(fword(r, 0, "color", 1), -1.0f);
  EXPECT_EQ(fword(r, 0, "color", 2), 1.0f);
  EXPECT_EQ(fword(r, 0, "color", 3), -1.0f);
  EXPECT_EQ(fword(r, 0, "hit_position", 0), 1.0f);
  EXPECT_EQ(fword(r, 0, "hit_position", 1), 1.0f);
  // Ray 1 (object -0.5, 0.25) is in triangle 1 (0, 2, 3): third vertex -1, 1.
  EXPECT_EQ(fword(r, 1, "color", 2), 1.0f);
  EXPECT_EQ(fword(r, 1, "color", 3), 1.0f);
  EXPECT_EQ(fword(r, 1, "hit_position", 0), -1.0f);
  EXPECT_EQ(fword(r, 1, "hit_position", 1), 1.0f);
}

TEST(PositionFetch, TheGeometryTransformApplies) {
  const Case c = parseInline(caseText("[2, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, -3]"));
  const Results r = runTier(c, ModelTier::Exact);
  EXPECT_EQ(fword(r, 0, "hit_position", 0), 2.5f);  // 2 * 1 + 0.5
  EXPECT_EQ(fword(r, 0, "hit_position", 2), -3.0f);
}

TEST(PositionFetch, TheWorldSpaceFaultMovesThem) {
  Case c = parseInline(caseText(kIdentityRows));
  ModelOptions o{ModelTier::Exact, 2};
  o.faults.position_fetch_world_space = true;
  const Results r = runOnModel(c, derivePlan(c), o);
  EXPECT_EQ(fword(r, 0, "hit_position", 0), 12.0f);  // 10 + 2 * 1
}

TEST(PositionFetch, AGroupWithAnIntersectionShaderMayNotReadIt) {
  const ParseResult p =
      parseCaseText(caseText(kIdentityRows, "      intersection: [report: {t: 1.0, kind: 1}]\n"),
                    "t.yaml", "t/t");
  ASSERT_FALSE(p.errors.empty());
  const std::string e = p.errors[0].format();
  EXPECT_NE(e.find("t.yaml:"), std::string::npos) << e;
  EXPECT_NE(e.find("vertex_position2"), std::string::npos) << e;
  EXPECT_NE(e.find("08750"), std::string::npos) << e;
}

}  // namespace
}  // namespace rayspec::model_test
