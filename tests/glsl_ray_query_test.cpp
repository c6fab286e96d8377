// Raygen's traces as ray query loops (glsl/emit_ray_query.h): the generated
// raygen traces no ray, runs the query loop and the inlined programs, reads
// built-ins through the query, and compiles to valid SPIR-V.
#include <gtest/gtest.h>

#include <string>

#include "case/flag_names.h"
#include "glsl/bindings.h"
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

// The SBT's tables (glsl/bindings.h): hit groups, miss programs, then the
// records' data words, each record `record_data / 4` words.
TEST(SbtTables, GroupsMissProgramsAndDataInOrder) {
  Pipeline p;
  p.hit_groups.resize(2);
  p.miss.resize(1);
  p.sbt_record_data = 8;
  p.sbt_hit = {{1u, {7, 8}}, {std::nullopt, {}}, {0u, {9}}};
  p.sbt_miss = {{0u, {5, 6}}, {3u, {}}};  // miss program 3 does not exist
  const SbtTables t = packSbtTables(p);
  EXPECT_EQ(t.hit_records, 3u);
  EXPECT_EQ(t.miss_records, 2u);
  EXPECT_EQ(t.record_words, 2u);
  EXPECT_EQ(t.hit_groups, 0u);
  EXPECT_EQ(t.miss_groups, 3u);
  EXPECT_EQ(t.hit_data, 5u);
  EXPECT_EQ(t.miss_data, 11u);
  EXPECT_EQ(t.words, (std::vector<uint32_t>{1, kSbtNoGroup, 0, 0, kSbtNoGroup, 7, 8, 0, 0, 9, 0, 5,
                                            6, 0, 0}));
  // Without SBT lists record i is group / miss program i, its data zero.
  Pipeline d;
  d.hit_groups.resize(2);
  d.miss.resize(1);
  d.sbt_record_data = 4;
  EXPECT_EQ(packSbtTables(d).words, (std::vector<uint32_t>{0, 1, 0, 0, 0, 0}));
  // Never empty: a buffer of one word at least.
  EXPECT_EQ(packSbtTables(Pipeline{}).words.size(), 1u);
}

// The inlined programs read the SBT from its buffer, not from constant
// arrays: lavapipe 25 compiled sbt/hit-index-aabbs's 325 records of 8 words
// as GLSL constants for over 10 minutes (a cold through/ray-query run).
TEST(RayQueryGlsl, TheSbtIsReadFromItsTablesBuffer) {
  const std::optional<CaseFile> f = suiteCase("sbt/hit-index-aabbs/offset-3-stride-0x11");
  ASSERT_TRUE(f);
  const ParseResult parsed = loadSuiteCase(*f);
  ASSERT_TRUE(parsed.value);
  EXPECT_FALSE(derivePlan(*parsed.value).sbt_tables);
  Case c = *parsed.value;
  c.pipeline.ray_query = true;  // as --through ray-query sends it
  const Plan plan = derivePlan(c);
  EXPECT_TRUE(plan.sbt_tables);
  const std::string g = generateGlsl(c, plan).raygen.glsl;
  for (const char* needle :
       {"binding = RS_BINDING_SBT_TABLES", "kRsHitRecords = 325u", "kRsRecordWords = 8u",
        "rs_sbt_tables[kRsHitGroups + record]", "rs_sbt_tables[kRsHitData + rs_q_hit_record",
        "rs_sbt_tables[kRsMissGroups + rs_q_miss_record]"})
    EXPECT_NE(g.find(needle), std::string::npos) << needle;
  EXPECT_EQ(g.find("uint[]("), std::string::npos) << "a constant table";
  const SpirvResult r = compileGlsl(g, Stage::Raygen);
  EXPECT_TRUE(r.error.empty()) << r.error;
}

size_t countIn(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

// recursion/depth-three (max_recursion 3, closest-hit traces): three levels,
// each its own query (level L > 1 by #define), loop and trace function, the
// deepest first; the last level's trace is skipped, as the model skips it.
TEST(RayQueryGlsl, NestedTracesAreOneQueryPerLevel) {
  Case c = suiteCaseFile("recursion/depth-three");
  c.pipeline.ray_query = true;
  const std::string g = generateGlsl(c, derivePlan(c)).raygen.glsl;
  EXPECT_EQ(countIn(g, "while (rayQueryProceedEXT(rs_rq))"), 3u);
  EXPECT_EQ(countIn(g, "rayQueryEXT rs_rq;"), 3u);
  for (const char* needle :
       {"#define rs_rq rs_rq_d2", "#define rs_rq rs_rq_d3", "void rs_trace_d3(",
        "void rs_trace_d2(", "void rs_trace(", "void rs_closest_hit_0_d2(",
        "void rs_closest_hit_0_d3(", "beyond pipeline.max_recursion"})
    EXPECT_NE(g.find(needle), std::string::npos) << needle;
  EXPECT_LT(g.find("void rs_trace_d3("), g.find("void rs_trace_d2("));
  EXPECT_LT(g.find("void rs_trace_d2("), g.find("void rs_trace("));
  // Level 1's closest-hit calls level 2's trace, level 2's level 3's.
  EXPECT_NE(g.find("rs_trace_d2(rs_payload_0"), std::string::npos);
  EXPECT_NE(g.find("rs_trace_d3(rs_payload_0"), std::string::npos);
  EXPECT_EQ(g.find("traceRayEXT("), std::string::npos);
  const SpirvResult r = compileGlsl(g, Stage::Raygen);
  EXPECT_TRUE(r.error.empty()) << r.error;
}

// ray_query_in_hit: raygen keeps traceRayEXT; the closest-hit hosts its own
// trace's query and max_recursion - 1 levels of inlined programs.
TEST(RayQueryGlsl, InHitTheClosestHitHostsItsTraces) {
  Case c = suiteCaseFile("recursion/depth-three");
  c.pipeline.ray_query_in_hit = true;
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  EXPECT_NE(g.raygen.glsl.find("traceRayEXT("), std::string::npos);
  EXPECT_EQ(g.raygen.glsl.find("rayQuery"), std::string::npos);
  const std::string& chit = g.hit_groups.at(0).closest_hit->glsl;
  EXPECT_EQ(chit.find("traceRayEXT("), std::string::npos);
  EXPECT_EQ(countIn(chit, "while (rayQueryProceedEXT(rs_rq))"), 2u);
  EXPECT_NE(chit.find("rs_trace(rs_payload_0"), std::string::npos);
  const SpirvResult r = compileGlsl(chit, Stage::ClosestHit);
  EXPECT_TRUE(r.error.empty()) << r.error;
}

// An any-hit's ignore and terminate inside an invoked function: the function
// sets the verdict and returns, the any-hit returns it after the invoke.
TEST(RayQueryGlsl, FunctionsOfAnInlinedAnyHitPassTheVerdictBack) {
  const std::optional<CaseFile> f = suiteCase("control/any-hit-functions/nested-stop-1");
  ASSERT_TRUE(f);
  const ParseResult parsed = loadSuiteCase(*f);
  ASSERT_TRUE(parsed.value);
  Case c = *parsed.value;
  c.pipeline.ray_query = true;
  const std::string g = generateGlsl(c, derivePlan(c)).raygen.glsl;
  for (const char* needle :
       {"void rs_fn_inner_hit0_any_hit(uint v_layer, uint v_stop, inout RsPayload payload",
        "inout uint rs_ah_verdict)", "rs_ah_verdict = kRsIgnore; return;",
        "rs_ah_verdict = kRsTerminate; return;", "if (rs_ah_verdict != kRsAccept) return;",
        "if (rs_ah_verdict != kRsAccept) return rs_ah_verdict;", "uint rs_ah_verdict = kRsAccept;"})
    EXPECT_NE(g.find(needle), std::string::npos) << needle;
  const SpirvResult r = compileGlsl(g, Stage::Raygen);
  EXPECT_TRUE(r.error.empty()) << r.error;
}

}  // namespace
}  // namespace rayspec
