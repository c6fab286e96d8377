// Raygen's traces as ray query loops (glsl/emit_ray_query.h): the generated
// raygen traces no ray, runs the query loop and the inlined programs, reads
// built-ins through the query, and compiles to valid SPIR-V.
#include <gtest/gtest.h>

#include <string>

#include "case/flag_names.h"
#include "glsl/generate_glsl.h"
#include "spirv/compile_glsl.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

TEST(RayQueryGlsl, RaygenRunsTheLoopAndTheInlinedPrograms) {
  const Case c = suiteCaseFile("ray-query/any-hit-and-intersection");
  ASSERT_TRUE(c.pipeline.ray_query);
  const Plan plan = derivePlan(c);
  const GeneratedShader raygen = generateGlsl(c, plan).raygen;
  const std::string& g = raygen.glsl;
  EXPECT_EQ(g.find("traceRayEXT("), std::string::npos);
  for (const char* needle :
       {"#extension GL_EXT_ray_query : require", "while (rayQueryProceedEXT(rs_rq))",
        "rayQueryConfirmIntersectionEXT(rs_rq);", "rayQueryGenerateIntersectionEXT(rs_rq, rs_t);",
        "uint rs_any_hit_0(", "void rs_intersection_1(", "bool rs_report_1(",
        "void rs_closest_hit_0(", "void rs_miss_0(",
        "rayQueryGetIntersectionInstanceIdEXT(rs_rq, false)"})
    EXPECT_NE(g.find(needle), std::string::npos) << needle;
  // No stage's own interface: the inlined programs read the query.
  const size_t inlined = g.find("// ---- the hit group and miss programs, inlined at level 1 ----");
  ASSERT_NE(inlined, std::string::npos);
  for (const char* stage_only : {"gl_PrimitiveID", "gl_InstanceID", "gl_HitKindEXT",
                                 "gl_ObjectRayOriginEXT", "reportIntersectionEXT"})
    EXPECT_EQ(g.find(stage_only, inlined), std::string::npos) << stage_only;
  const SpirvResult r = compileGlsl(g, Stage::Raygen);
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_FALSE(r.words.empty());
}

// The pipeline's skip_triangles / skip_aabbs act on traceRayEXT alone: the
// query takes them as ray flags (0x100, 0x200), gl_IncomingRayFlagsEXT not.
TEST(RayQueryGlsl, PipelineSkipFlagsBecomeTheQuerysRayFlags) {
  Case c = suiteCaseFile("ray-query/any-hit-and-intersection");
  c.pipeline.flags = kPipelineSkipTriangles | kPipelineSkipAabbs;
  const std::string g = generateGlsl(c, derivePlan(c)).raygen.glsl;
  EXPECT_NE(g.find("(rs_flags & ~gl_RayFlagsSkipClosestHitShaderEXT) | 768u"), std::string::npos)
      << g;
  EXPECT_NE(g.find("rs_q_flags = rs_flags;"), std::string::npos);
  c.pipeline.flags = 0;
  EXPECT_EQ(generateGlsl(c, derivePlan(c)).raygen.glsl.find("| 768u"), std::string::npos);
}

TEST(RayQueryGlsl, ThePipelineFormIsUnchanged) {
  Case c = suiteCaseFile("ray-query/any-hit-and-intersection");
  c.pipeline.ray_query = false;
  const std::string g = generateGlsl(c, derivePlan(c)).raygen.glsl;
  EXPECT_NE(g.find("traceRayEXT("), std::string::npos);
  EXPECT_EQ(g.find("rayQuery"), std::string::npos);
}

}  // namespace
}  // namespace rayspec
