// Raygen run as a compute shader (glsl/emit_compute.h): the dispatch covers
// the launch, the shader is a compute shader that compiles, reads its launch
// id from the dispatch and declares nothing of a ray tracing stage.
#include <gtest/gtest.h>

#include <string>

#include "glsl/emit_compute.h"
#include "glsl/generate_glsl.h"
#include "program/ops.h"
#include "spirv/compile_glsl.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

uint64_t invocationsOf(const std::array<uint32_t, 3>& groups) {
  return uint64_t{groups[0]} * groups[1] * groups[2] * kComputeGroupSize;
}

TEST(ComputeGlsl, TheDispatchCoversTheLaunchWithinTheGroupLimits) {
  EXPECT_EQ(computeGroups({0, 5, 1}), (std::array<uint32_t, 3>{0, 0, 0}));
  EXPECT_EQ(computeGroups({64, 1, 1}), (std::array<uint32_t, 3>{1, 1, 1}));
  EXPECT_EQ(computeGroups({65, 1, 1}), (std::array<uint32_t, 3>{2, 1, 1}));
  EXPECT_EQ(computeGroups({23, 17, 1}), (std::array<uint32_t, 3>{7, 1, 1}));
  // 2^22 ids: 65536 groups, one more than x may hold.
  EXPECT_EQ(computeGroups({4194304, 1, 1}), (std::array<uint32_t, 3>{kComputeMaxGroupsX, 2, 1}));
  for (const std::array<uint32_t, 3> launch :
       {std::array<uint32_t, 3>{7, 5, 3}, std::array<uint32_t, 3>{1u << 15, 1u << 10, 2}}) {
    const std::array<uint32_t, 3> g = computeGroups(launch);
    const uint64_t ids = uint64_t{launch[0]} * launch[1] * launch[2];
    EXPECT_GE(invocationsOf(g), ids);
    EXPECT_LT(invocationsOf(g), ids + uint64_t{g[0]} * kComputeGroupSize);
    EXPECT_LE(g[0], kComputeMaxGroupsX);
    EXPECT_LE(g[1], kComputeMaxGroupsX);
  }
}

TEST(ComputeGlsl, RaygenIsACompiledComputeShaderAndTheOnlyStage) {
  const Case c = suiteCaseFile("ray-query/compute-any-hit-and-intersection");
  ASSERT_TRUE(c.pipeline.ray_query && c.pipeline.from_compute);
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  ASSERT_EQ(everyStage(g).size(), 1u);
  EXPECT_TRUE(g.raygen.compute);
  const std::string& glsl = g.raygen.glsl;
  for (const char* needle : {"layout(local_size_x = 64) in;", "#define RS_LAUNCH_ID rs_launch_id",
                             "gl_GlobalInvocationID", "while (rayQueryProceedEXT(rs_rq))"})
    EXPECT_NE(glsl.find(needle), std::string::npos) << needle;
  for (const char* ray_tracing_only :
       {"GL_EXT_ray_tracing", "rayPayloadEXT", "traceRayEXT(",
        "#define RS_LAUNCH_ID gl_LaunchIDEXT", "#define RS_USE_SHADER_RECORD"})
    EXPECT_EQ(glsl.find(ray_tracing_only), std::string::npos) << ray_tracing_only;
  const SpirvResult compute = compileGlsl(glsl, Stage::Raygen, true);
  EXPECT_TRUE(compute.error.empty()) << compute.error;
  // The same text is no ray generation shader (no ray tracing extension).
  EXPECT_FALSE(compileGlsl(glsl, Stage::Raygen).error.empty());
}

// Raygen's shader record data becomes a constant table.
TEST(ComputeGlsl, RaygenRecordDataIsAConstantTable) {
  Case c = suiteCaseFile("ray-query/compute-query-in-loop");
  c.pipeline.raygen_data = {7u, 9u};
  Stmt read;
  read.kind = Stmt::Kind::Record;
  Expr word;
  word.kind = Expr::Kind::Op;
  setOp(word, Op::RecordUint);
  word.type = ValueType::Uint;
  Expr one;
  one.kind = Expr::Kind::Literal;
  one.type = ValueType::Uint;
  one.literal = {1.0};
  word.args = {one};
  read.assigns = {{"value", word}};
  c.pipeline.raygen.push_back(read);
  const std::string glsl = generateGlsl(c, derivePlan(c)).raygen.glsl;
  EXPECT_NE(glsl.find("const uint kRsRaygenRecord["), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("= uint[](7u, 9u"), std::string::npos);
  EXPECT_TRUE(compileGlsl(glsl, Stage::Raygen, true).error.empty());
}

}  // namespace
}  // namespace rayspec
