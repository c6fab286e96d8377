// The GLSL of vertex_position<i> (gl_HitTriangleVertexPositionsEXT): glslang 12
// has no GL_EXT_ray_tracing_position_fetch, so shaders/position_fetch.glsl
// declares the built-in through GL_EXT_spirv_intrinsics; only the stages that
// read it declare it, and the module compiles (validation is left to the
// layer where SPIRV-Tools predates the capability). A ray query's positions
// (candidate.*, committed.*, and vertex_position<i> of an inlined stage) are
// OpRayQueryGetIntersectionTriangleVertexPositionsKHR, declared the same way
// (shaders/query_position_fetch.glsl).
#include <gtest/gtest.h>

#include "glsl/generate_glsl.h"
#include "parse_support.h"
#include "plan/plan.h"
#include "spirv/compile_glsl.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

Case positionCase() {
  return parsedCase(
      "rules: [R-POSITION-FETCH]\n"
      "scene:\n"
      "  blas:\n"
      "    tri: [{triangles: {vertices: [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]}}]\n"
      "  instances: [{blas: tri}]\n"
      "rays:\n"
      "  list: [{origin: [0, 0, 5], direction: [0, 0, -1]}]\n"
      "pipeline:\n"
      "  hit_groups:\n"
      "    - closest_hit: [record: {hit_position: vertex_position2}]\n"
      "outputs:\n"
      "  per_ray: [hit_position]\n");
}

TEST(PositionFetch, TheGlslDeclaresTheBuiltInAndCompiles) {
  const Case c = positionCase();
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  ASSERT_TRUE(g.hit_groups.at(0).closest_hit);
  const std::string& glsl = g.hit_groups[0].closest_hit->glsl;
  EXPECT_NE(glsl.find("#extension GL_EXT_spirv_intrinsics : require"), std::string::npos);
  EXPECT_NE(glsl.find("spirv_decorate(extensions = [\"SPV_KHR_ray_tracing_position_fetch\"]"),
            std::string::npos);
  EXPECT_NE(glsl.find("rs_hit_positions[2]"), std::string::npos);
  const SpirvResult spirv = compileGlsl(glsl, Stage::ClosestHit);
  EXPECT_TRUE(spirv.error.empty()) << spirv.error;
  EXPECT_EQ(g.raygen.glsl.find("rs_hit_positions"), std::string::npos);
}

TEST(PositionFetch, ThePlanAsksForTheExtension) {
  EXPECT_TRUE(derivePlan(positionCase()).position_fetch);
}

// Whether the module holds an instruction `opcode` whose word `at` (1 = the
// result type) is `value`, or any such instruction when at is 0.
bool holds(const std::vector<uint32_t>& words, uint32_t opcode, uint32_t at = 0,
           uint32_t value = 0) {
  for (size_t i = 5; i < words.size();) {
    const uint32_t count = words[i] >> 16;
    if ((words[i] & 0xFFFF) == opcode && (at == 0 || (at < count && words[i + at] == value)))
      return true;
    i += count ? count : 1;
  }
  return false;
}

constexpr uint32_t kOpCapability = 17, kRayQueryPositionFetch = 5391, kOpRayQueryPositions = 5340;

TEST(PositionFetch, AnInlinedClosestHitReadsThemThroughTheQuery) {
  Case c = positionCase();
  c.pipeline.ray_query = true;
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  const std::string& glsl = g.raygen.glsl;
  EXPECT_NE(glsl.find("rs_query_positions(rs_rq, uint(true))[2]"), std::string::npos) << glsl;
  EXPECT_EQ(glsl.find("rs_hit_positions"), std::string::npos);  // no hit built-in in raygen
  const SpirvResult spirv = compileGlsl(glsl, Stage::Raygen);
  ASSERT_TRUE(spirv.error.empty()) << spirv.error;
  EXPECT_TRUE(holds(spirv.words, kOpCapability, 1, kRayQueryPositionFetch));
  EXPECT_TRUE(holds(spirv.words, kOpRayQueryPositions));
}

TEST(PositionFetch, TheQueryGettersCompileForCandidateAndCommitted) {
  const Case c = suiteCaseFile("ray-query/position-fetch");
  const Plan plan = derivePlan(c);
  EXPECT_TRUE(plan.position_fetch);
  const std::string& glsl = generateGlsl(c, plan).raygen.glsl;
  EXPECT_NE(glsl.find("rs_query_positions(rs_query, 0u)[1]"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("rs_query_positions(rs_query, 1u)[0]"), std::string::npos);
  const SpirvResult spirv = compileGlsl(glsl, Stage::Raygen);
  ASSERT_TRUE(spirv.error.empty()) << spirv.error;
  EXPECT_TRUE(holds(spirv.words, kOpRayQueryPositions));
}

}  // namespace
}  // namespace rayspec
