// sphere_hit, sphere_near and sphere_far in a ray query's aabb block: the
// query's AABB candidate's box against its object-space ray (program/ops.h),
// where the checks allow them, what the model commits for each ray of
// cases/ray-query/sphere-crossing, and the tangent ray's two legal answers.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "model/model_engine.h"
#include "model_support.h"
#include "parse/parse_case.h"

namespace rayspec {
namespace {

using namespace model_test;

Case crossingCase() {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(RAYSPEC_SOURCE_DIR) / "cases";
  ParseResult p = parseCaseFile((root / "ray-query/sphere-crossing.yaml").string(), root.string());
  EXPECT_TRUE(p.value && p.errors.empty());
  return p.value ? *p.value : Case{};
}

// A raygen query whose `block` (a statement list) reads a sphere op.
const char* kQuery = R"(rules: [R-RQ-COMMIT]
scene:
  blas:
    b:
      - aabbs: [[-1, -1, -1, 1, 1, 1]]
  instances: [{blas: b}]
rays:
  list: [{origin: [0, 0, 5], direction: [0, 0, -1]}]
pipeline:
  raygen:
    - ray_query:
        aabb: [{if: sphere_hit, then: [generate: query.ray_tmin]}]
        after: [record: {value: committed.type}]
outputs:
  per_ray: [value]
)";

TEST(QuerySphere, OnlyInAnAabbBlockOutsideIntersection) {
  const std::string q = kQuery, aabb = "aabb: [{if: sphere_hit, then: [generate: query.ray_tmin]}]";
  EXPECT_EQ(firstErrorAfter(q, "value", "value"), "(no error)");
  EXPECT_NE(firstErrorAfter(q, aabb, "triangle: [{if: sphere_hit, then: [confirm]}]")
                .find("only in intersection, or in a ray_query's aabb block"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(q, "committed.type}]", "{float_bits: sphere_far}}]")
                .find("only in intersection, or in a ray_query's aabb block"),
            std::string::npos);
  // An intersection program's sphere ops read its own box: not in its query's aabb block.
  const std::string own =
      "pipeline:\n  hit_groups:\n    - intersection:\n        - ray_query:\n            "
      "origin: world_ray_origin\n            direction: [0, 0, -1]\n            aabb: [{if: "
      "sphere_hit, then: [generate: query.ray_tmin]}]\n  raygen:";
  std::string text = q;
  text.replace(text.find("pipeline:\n  raygen:"), 19, own);
  const ParseResult p = parseCaseText(text, "model/inline.yaml", "model/inline");
  ASSERT_FALSE(p.errors.empty());
  EXPECT_NE(p.errors[0].message.find("reads its own box: not in a ray_query's aabb block"),
            std::string::npos)
      << p.errors[0].message;
}

// Each ray as the case's description says: committed where the ray crosses
// a sphere (t its near root), nothing where it only enters a box's corner,
// passes between boxes or starts inside a sphere; the triangle in front of
// a box, the box in front of a triangle.
TEST(QuerySphere, CommitsWhereTheRayCrossesTheSphere) {
  const Case c = crossingCase();
  const Results r = runTier(c, ModelTier::Exact, 1);
  ASSERT_EQ(r.statusText(), "ok");
  const uint32_t none = 0, triangle = 1, generated = 2;
  const std::map<uint32_t, uint32_t> type = {{0, generated}, {1, generated}, {2, none},
                                             {3, generated}, {4, none},      {5, none},
                                             {6, none},      {7, triangle},  {8, generated}};
  for (const auto& [ray, t] : type) EXPECT_EQ(word(r, ray, "value"), t) << "ray " << ray;
  EXPECT_NEAR(fword(r, 0, "color"), 9.0, 1e-5);
  EXPECT_NEAR(fword(r, 1, "color"), 10.0 - std::sqrt(0.5), 1e-5);
  EXPECT_EQ(word(r, 3, "value1"), 1u);  // the scaled, rotated instance
  EXPECT_EQ(word(r, 3, "value2"), 7u);
  EXPECT_EQ(word(r, 7, "value1"), 2u);  // the wall's triangle
  EXPECT_EQ(word(r, 8, "value3"), 3u);  // the box in front of the other wall
  EXPECT_NEAR(fword(r, 8, "color"), 9.0, 1e-5);
}

// The ray tangent to a sphere: sphere_hit is numerically ambiguous, and both
// answers (the box committed at t 10, or nothing) are legal. The box behind
// a triangle and the box in front of one: the exact tier tries both orders,
// and each leaves the one answer.
TEST(QuerySphere, TangentRayHasBothAnswersOtherOrdersOne) {
  const Results r = runTier(crossingCase(), ModelTier::Exact, 1);
  std::map<uint32_t, const RayAmbiguity*> amb;
  for (const RayAmbiguity& a : r.ambiguous) amb[a.ray] = &a;
  ASSERT_EQ(amb.size(), 3u);
  ASSERT_EQ(amb.count(9), 1u);
  EXPECT_EQ(amb[9]->reason, AmbiguityReason::ShaderArith);
  bool hit = false, miss = false;
  for (const Candidate& k : amb[9]->candidates) (k.hit ? hit : miss) = true;
  EXPECT_TRUE(hit && miss);
  for (uint32_t ray : {7u, 8u}) {
    ASSERT_EQ(amb.count(ray), 1u) << ray;
    ASSERT_EQ(amb[ray]->candidates.size(), 1u) << ray;
    EXPECT_TRUE(amb[ray]->candidates[0].hit) << ray;
  }
}

}  // namespace
}  // namespace rayspec
