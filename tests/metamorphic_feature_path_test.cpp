// --through (metamorphic/feature_path.h): each feature path changes only how
// the case is launched or built, and a case that takes its own way there is
// left alone with the reason.
#include <gtest/gtest.h>

#include "case/flag_names.h"
#include "metamorphic/feature_path.h"
#include "parse_support.h"
#include "result_support.h"

namespace rayspec {
namespace {

Case simpleCase(const std::string& extra_scene = "", const std::string& extra_rays = "") {
  return parsedCase(
      "rules: [R-MASK]\n"
      "scene:\n"
      "  blas:\n"
      "    tri: [{triangles: {vertices: [[-1, -1, 0], [1, -1, 0], [-1, 1, 0]]}}]\n"
      "  instances: [{blas: tri}]\n" +
      extra_scene +
      "rays:\n"
      "  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]\n" +
      extra_rays +
      "pipeline:\n"
      "  miss: [[record: {hit: 0}]]\n"
      "  hit_groups: [{closest_hit: [record: [hit]]}]\n"
      "  callables: [[call_data: {value: 1}]]\n"
      "outputs:\n"
      "  per_ray: [hit]\n");
}

TEST(FeaturePath, NamesRoundTrip) {
  for (FeaturePath p : {FeaturePath::Indirect, FeaturePath::Indirect2, FeaturePath::Libraries,
                        FeaturePath::Clone, FeaturePath::Compact, FeaturePath::Serialize,
                        FeaturePath::Update, FeaturePath::RayQuery, FeaturePath::RayQueryCompute,
                        FeaturePath::RayQueryInHit, FeaturePath::Layouts, FeaturePath::OneByOne,
                        FeaturePath::UpdateIntoOther, FeaturePath::Generic, FeaturePath::Sparse})
    EXPECT_EQ(featurePathFromName(featurePathName(p)), p) << featurePathName(p);
  EXPECT_FALSE(featurePathFromName("sideways"));
  EXPECT_NE(featurePathNames().find("serialize"), std::string::npos);
}

TEST(FeaturePath, EachPathChangesItsOwnField) {
  const Case c = simpleCase();
  std::string why;
  EXPECT_EQ(valueOrMessage(throughPath(c, FeaturePath::Indirect), &why)->rays.command,
            TraceCommand::Indirect);
  EXPECT_EQ(valueOrMessage(throughPath(c, FeaturePath::Indirect2), &why)->rays.command,
            TraceCommand::Indirect2);
  EXPECT_EQ(valueOrMessage(throughPath(c, FeaturePath::Serialize), &why)->scene.build.copy,
            AsCopy::Serialize);
  EXPECT_EQ(valueOrMessage(throughPath(c, FeaturePath::Compact), &why)->scene.build.copy,
            AsCopy::Compact);
  const Case lib = *valueOrMessage(throughPath(c, FeaturePath::Libraries), &why);
  ASSERT_EQ(lib.pipeline.libraries.size(), 1u);
  EXPECT_EQ(lib.pipeline.libraries[0].miss, (std::vector<uint32_t>{0}));
  EXPECT_EQ(lib.pipeline.libraries[0].hit_groups, (std::vector<uint32_t>{0}));
  EXPECT_EQ(lib.pipeline.libraries[0].callables, (std::vector<uint32_t>{0}));
  const Case updated = *valueOrMessage(throughPath(c, FeaturePath::Update), &why);
  ASSERT_EQ(updated.scene.updates(), 1u);
  EXPECT_TRUE(updated.scene.build.flags & kBuildAllowUpdate);
  EXPECT_EQ(updated.scene.earlier.front()->instances.size(), c.scene.instances.size());
  EXPECT_EQ(updated.scene.blases[0].geometries[0].vertices,
            updated.scene.earlier.front()->blases[0].geometries[0].vertices);
  EXPECT_TRUE(valueOrMessage(throughPath(c, FeaturePath::RayQuery), &why)->pipeline.ray_query);
  const Case computed = *valueOrMessage(throughPath(c, FeaturePath::RayQueryCompute), &why);
  EXPECT_TRUE(computed.pipeline.ray_query && computed.pipeline.from_compute);
  EXPECT_FALSE(valueOrMessage(throughPath(c, FeaturePath::RayQuery), &why)->pipeline.from_compute);
  EXPECT_TRUE(valueOrMessage(throughPath(c, FeaturePath::OneByOne), &why)->scene.build.one_by_one);
  const Case into = *valueOrMessage(throughPath(c, FeaturePath::UpdateIntoOther), &why);
  EXPECT_TRUE(into.scene.build.update_into_other);
  EXPECT_EQ(into.scene.updates(), 1u);  // no update of its own: one to the same scene
  const Case twice = *valueOrMessage(throughPath(into, FeaturePath::UpdateIntoOther), &why);
  EXPECT_EQ(twice.scene.updates(), 1u);  // its own update kept, not another added
  Case copied = c;
  copied.scene.build.copy = AsCopy::Clone;
  EXPECT_FALSE(valueOrMessage(throughPath(copied, FeaturePath::UpdateIntoOther), &why));
  EXPECT_NE(why.find("copies"), std::string::npos) << why;
}

// generic creates every structure of both levels GENERIC, sparse binds
// them sparsely; a case that already does is not sent again.
TEST(FeaturePath, GenericAndSparseSetTheirBuildFields) {
  const Case c = simpleCase();
  std::string why;
  const Case generic = *valueOrMessage(throughPath(c, FeaturePath::Generic), &why);
  EXPECT_EQ(generic.scene.build.generic, GenericLevels::Both);
  EXPECT_FALSE(generic.scene.build.sparse.any());
  const Case sparse = *valueOrMessage(throughPath(c, FeaturePath::Sparse), &why);
  EXPECT_TRUE(sparse.scene.build.sparse.all());
  EXPECT_EQ(sparse.scene.build.generic, GenericLevels::None);
  Case own = c;
  own.scene.build.generic = GenericLevels::Top;
  EXPECT_FALSE(valueOrMessage(throughPath(own, FeaturePath::Generic), &why));
  EXPECT_NE(why.find("GENERIC"), std::string::npos) << why;
  EXPECT_FALSE(valueOrMessage(throughPath(sparse, FeaturePath::Sparse), &why));
  EXPECT_NE(why.find("sparsely"), std::string::npos) << why;
}

// What the ray query form cannot express keeps a case off the path, named.
TEST(FeaturePath, RayQueryRefusesWhatItCannotInline) {
  std::string why;
  const Case own = *valueOrMessage(throughPath(simpleCase(), FeaturePath::RayQuery), &why);
  EXPECT_FALSE(valueOrMessage(throughPath(own, FeaturePath::RayQuery), &why));
  EXPECT_NE(why.find("by ray query itself"), std::string::npos) << why;
  Case nested = simpleCase();
  Stmt trace;
  trace.kind = Stmt::Kind::Trace;
  nested.pipeline.hit_groups[0].closest_hit->push_back(trace);
  nested.pipeline.hit_groups[0].closest_hit->push_back(trace);
  nested.pipeline.max_recursion = 2;  // 1 + 2 copies of the inlined programs
  EXPECT_TRUE(valueOrMessage(throughPath(nested, FeaturePath::RayQuery), &why)) << why;
  nested.pipeline.max_recursion = 7;  // 1 + 2 + ... + 64
  EXPECT_FALSE(valueOrMessage(throughPath(nested, FeaturePath::RayQuery), &why));
  EXPECT_NE(why.find("more than 64 copies"), std::string::npos) << why;
  Case typed = simpleCase();
  typed.pipeline.payload_words = {0, 2};
  EXPECT_FALSE(valueOrMessage(throughPath(typed, FeaturePath::RayQuery), &why));
  EXPECT_NE(why.find("several payload types"), std::string::npos) << why;
  // The pipeline's skip flags become the query's ray flags: no obstacle.
  Case flagged = simpleCase();
  flagged.pipeline.flags = kPipelineSkipTriangles;
  EXPECT_TRUE(valueOrMessage(throughPath(flagged, FeaturePath::RayQuery), &why)) << why;
}

// The in-hit form: only a case whose closest-hit or miss traces goes, and
// raygen keeps traceRayEXT (ray_query stays off).
TEST(FeaturePath, RayQueryInHitTakesCasesThatTraceFromHitOrMiss) {
  std::string why;
  EXPECT_FALSE(valueOrMessage(throughPath(simpleCase(), FeaturePath::RayQueryInHit), &why));
  EXPECT_NE(why.find("no closest-hit or miss traces"), std::string::npos) << why;
  Case nested = simpleCase();
  Stmt trace;
  trace.kind = Stmt::Kind::Trace;
  nested.pipeline.miss[0].push_back(trace);
  nested.pipeline.max_recursion = 3;
  const Case in_hit = *valueOrMessage(throughPath(nested, FeaturePath::RayQueryInHit), &why);
  EXPECT_TRUE(in_hit.pipeline.ray_query_in_hit);
  EXPECT_FALSE(in_hit.pipeline.ray_query);
  EXPECT_FALSE(valueOrMessage(throughPath(in_hit, FeaturePath::RayQueryInHit), &why));
  EXPECT_NE(why.find("by ray query itself"), std::string::npos) << why;
  EXPECT_FALSE(valueOrMessage(throughPath(in_hit, FeaturePath::RayQuery), &why));
}

TEST(FeaturePath, LayoutsTurnsOnEveryLayout) {
  std::string why;
  const Case laid = *valueOrMessage(throughPath(simpleCase(), FeaturePath::Layouts), &why);
  EXPECT_TRUE(laid.scene.build.instances_as_pointers);
  EXPECT_TRUE(laid.scene.build.data_offsets);
  EXPECT_EQ(laid.scene.build.vertex_stride, kLayoutsVertexStride);
  EXPECT_EQ(laid.scene.build.aabb_stride, kLayoutsAabbStride);
  EXPECT_EQ(laid.scene.build.first_vertex, 0u) << "lavapipe 25.0.7 applies it twice";
  EXPECT_FALSE(valueOrMessage(throughPath(laid, FeaturePath::Layouts), &why));
  EXPECT_NE(why.find("lays its build inputs out itself"), std::string::npos) << why;
  // Every vertex format fits the path's stride: at least its size, a
  // multiple of its component.
  for (VertexFormat f : enumValues<VertexFormat>()) {
    EXPECT_GE(kLayoutsVertexStride, vertexStride(f)) << vertexFormatName(f);
    EXPECT_EQ(kLayoutsVertexStride % vertexComponentBytes(f), 0u) << vertexFormatName(f);
  }
}

TEST(FeaturePath, ACaseWithItsOwnWayThereIsLeftAlone) {
  std::string why;
  const Case copied = simpleCase("  build: {copy: clone}\n");
  EXPECT_FALSE(valueOrMessage(throughPath(copied, FeaturePath::Serialize), &why));
  EXPECT_NE(why.find("copies"), std::string::npos) << why;
  const Case indirect = simpleCase("", "  command: indirect2\n");
  EXPECT_FALSE(valueOrMessage(throughPath(indirect, FeaturePath::Indirect), &why));
  EXPECT_NE(why.find("launch command"), std::string::npos) << why;
  EXPECT_TRUE(valueOrMessage(throughPath(indirect, FeaturePath::Update), &why));
}

}  // namespace
}  // namespace rayspec
