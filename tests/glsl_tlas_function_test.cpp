// pipeline.tlas_function (glsl/tlas_function.h): every trace and ray query
// of a stage passes its top level, the array element it names, to a
// function taking an accelerationStructureEXT (qualified nonuniformEXT, so
// that the load inside is NonUniform); without it the element goes to
// traceRayEXT / rayQueryInitializeEXT directly. Both compile.
#include <gtest/gtest.h>

#include <string>

#include "glsl/generate_glsl.h"
#include "spirv/compile_glsl.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

Case variant(const char* name) {
  const std::optional<CaseFile> f = suiteCase(name);
  EXPECT_TRUE(f) << name;
  if (!f) return {};
  const ParseResult parsed = loadSuiteCase(*f);
  EXPECT_TRUE(parsed.value) << name;
  return parsed.value ? *parsed.value : Case{};
}

bool has(const std::string& text, const std::string& needle) {
  return text.find(needle) != std::string::npos;
}

const char* const kIndexed = "rs_tlas[nonuniformEXT(rs_tlas_i % 3u)]";

// raygen, miss 0 and closest-hit 0 of the case: each traces and queries.
std::vector<const GeneratedShader*> tracingStages(const GeneratedPipeline& g) {
  return {&g.raygen, &g.miss.at(0), &*g.hit_groups.at(0).closest_hit};
}

TEST(TlasFunction, EveryTraceAndQueryPassesTheElementToAFunction) {
  const Case c = variant("descriptors/tlas-array/through-function");
  ASSERT_TRUE(c.pipeline.tlas_function);
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  for (const GeneratedShader* s : tracingStages(g)) {
    SCOPED_TRACE(s->name);
    const std::string& t = s->glsl;
    const std::string at = s->stage == Stage::Raygen ? "0" : "1";  // the outgoing location
    EXPECT_TRUE(
        has(t, "void rs_trace_through_" + at + "(nonuniformEXT accelerationStructureEXT rs_as, "))
        << t;
    EXPECT_TRUE(has(t,
                    "traceRayEXT(rs_as, rs_flags, rs_cull_mask, rs_sbt_offset, rs_sbt_stride, "
                    "rs_miss, rs_origin, rs_tmin, rs_direction, rs_tmax, " +
                        at + ");"));
    EXPECT_TRUE(has(t, "rs_trace_through_" + at + "(" + kIndexed + ", rs_flags"));
    EXPECT_TRUE(has(
        t,
        "void rs_query_through(rayQueryEXT rs_q, nonuniformEXT accelerationStructureEXT rs_as, "));
    EXPECT_TRUE(has(t, "rs_query_through(rs_query_0, " + std::string(kIndexed) + ", rs_flags"));
    EXPECT_FALSE(has(t, "traceRayEXT(rs_tlas")) << t;
    EXPECT_FALSE(has(t, "rayQueryInitializeEXT(rs_query_0, rs_tlas")) << t;
    const SpirvResult r = compileGlsl(t, s->stage);
    EXPECT_TRUE(r.error.empty()) << r.error;
  }
}

TEST(TlasFunction, WithoutItTheElementGoesToTheCallItself) {
  const Case c = variant("descriptors/tlas-array/indexed");
  ASSERT_FALSE(c.pipeline.tlas_function);
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  for (const GeneratedShader* s : tracingStages(g)) {
    SCOPED_TRACE(s->name);
    EXPECT_FALSE(has(s->glsl, "rs_trace_through_"));
    EXPECT_FALSE(has(s->glsl, "rs_query_through"));
    EXPECT_TRUE(has(s->glsl, "traceRayEXT(" + std::string(kIndexed) + ", rs_flags"));
    const SpirvResult r = compileGlsl(s->glsl, s->stage);
    EXPECT_TRUE(r.error.empty()) << r.error;
  }
}

}  // namespace
}  // namespace rayspec
