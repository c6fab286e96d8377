// The GLSL of hit objects (GL_NV_shader_invocation_reorder, which glslang 12
// compiles): a stage that uses one enables the extension and declares a
// global hitObjectNV, empty at main's start; a trace into it is
// hitObjectTraceRayNV, execute is hitObjectExecuteShaderNV, and every stage
// of cases/ser/ compiles and validates (SPIRV-Tools 2023.1 knows
// SPV_NV_shader_invocation_reorder).
#include <gtest/gtest.h>

#include "glsl/generate_glsl.h"
#include "plan/plan.h"
#include "spirv/compile_glsl.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

TEST(GlslHitObject, TheRaygenTracesIntoItsHitObjectAndExecutesIt) {
  const Case c = suiteCaseFile("ser/execute");
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  const std::string& raygen = g.raygen.glsl;
  EXPECT_NE(raygen.find("#extension GL_NV_shader_invocation_reorder : require"), std::string::npos);
  EXPECT_NE(raygen.find("hitObjectNV rs_hit_object;"), std::string::npos);
  EXPECT_NE(raygen.find("hitObjectRecordEmptyNV(rs_hit_object);"), std::string::npos);
  EXPECT_NE(raygen.find("hitObjectTraceRayNV(rs_hit_object, rs_tlas, "), std::string::npos);
  EXPECT_NE(raygen.find("hitObjectExecuteShaderNV(rs_hit_object, 0);"), std::string::npos);
  EXPECT_EQ(raygen.find("traceRayEXT("), std::string::npos);
  // A stage that uses no hit object declares none.
  EXPECT_EQ(g.miss.at(0).glsl.find("hitObjectNV"), std::string::npos);
}

TEST(GlslHitObject, EveryStageOfTheSerCasesCompiles) {
  for (const char* name :
       {"ser/getters", "ser/execute", "ser/record-miss", "ser/reorder", "ser/nested",
        "ser/matrices", "ser/record-hit", "ser/record-hit-index", "ser/record-handle"}) {
    const Case c = suiteCaseFile(name);
    const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
    for (const GeneratedShader* s : everyStage(g)) {
      const SpirvResult spirv = compileGlsl(s->glsl, s->stage, s->compute);
      EXPECT_TRUE(spirv.error.empty()) << name << " " << s->name << ": " << spirv.error;
    }
  }
}

TEST(GlslHitObject, ReorderTakesTheHitObjectTheHintOrBoth) {
  const Case c = suiteCaseFile("ser/reorder");
  const std::string raygen = generateGlsl(c, derivePlan(c)).raygen.glsl;
  EXPECT_NE(raygen.find("reorderThreadNV(rs_hit_object);"), std::string::npos) << raygen;
  EXPECT_NE(raygen.find("reorderThreadNV(RS_LAUNCH_ID.x, 3u);"), std::string::npos);
  EXPECT_NE(raygen.find("reorderThreadNV(rs_hit_object, uint(hitObjectGetPrimitiveIndexNV("),
            std::string::npos);
}

TEST(GlslHitObject, ARecordedHitAndTheRecordHandle) {
  const Case c = suiteCaseFile("ser/record-hit");
  const std::string raygen = generateGlsl(c, derivePlan(c)).raygen.glsl;
  EXPECT_NE(raygen.find("hitObjectRecordHitNV(rs_hit_object, rs_tlas, int("), std::string::npos)
      << raygen;
  EXPECT_NE(raygen.find("rs_sbt_offset, rs_sbt_stride, rs_origin, rs_tmin, rs_direction, "
                        "rs_tmax, 0);"),
            std::string::npos);
  EXPECT_NE(raygen.find("rs_hit_object_attr = vec2("), std::string::npos);
  EXPECT_NE(raygen.find("#extension GL_EXT_buffer_reference_uvec2 : require"), std::string::npos);
  EXPECT_NE(raygen.find("hitobjectshaderrecordnv) buffer RsHitObjectRecord"), std::string::npos);
  EXPECT_NE(raygen.find("RsHitObjectRecord(hitObjectGetShaderRecordBufferHandleNV(rs_hit_object))"
                        ".words[0u]"),
            std::string::npos);
  const Case by_index = suiteCaseFile("ser/record-hit-index");
  EXPECT_NE(generateGlsl(by_index, derivePlan(by_index))
                .raygen.glsl.find("hitObjectRecordHitWithIndexNV(rs_hit_object, rs_tlas, int("),
            std::string::npos);
}

TEST(GlslHitObject, ThePlanAsksForTheExtension) {
  EXPECT_TRUE(derivePlan(suiteCaseFile("ser/record-miss")).hit_objects);
  EXPECT_FALSE(derivePlan(suiteCaseFile("results/miss-xor-closest-hit")).hit_objects);
}

}  // namespace
}  // namespace rayspec
