// The GLSL of vertex_position<i> (gl_HitTriangleVertexPositionsEXT): glslang 12
// has no GL_EXT_ray_tracing_position_fetch, so shaders/position_fetch.glsl
// declares the built-in through GL_EXT_spirv_intrinsics; only the stages that
// read it declare it, and the module compiles (validation is left to the
// layer where SPIRV-Tools predates the capability).
#include <gtest/gtest.h>

#include "case_support.h"
#include "glsl/generate_glsl.h"
#include "plan/plan.h"
#include "spirv/compile_glsl.h"

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

}  // namespace
}  // namespace rayspec
