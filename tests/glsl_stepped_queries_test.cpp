// ray_queries and restart_query as GLSL (glsl/emit_query.h): one array of
// rayQueryEXT stepped by a loop index, each element initialized, proceeded
// once a turn and decided by its own blocks, then each one's after; a
// restart initializes rs_query again (at most kMaxQueryRestarts times) and
// goes on to the next proceed. The SPIR-V compiles.
#include <gtest/gtest.h>

#include <string>

#include "glsl/generate_glsl.h"
#include "spirv/compile_glsl.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

std::string raygenOf(const char* name) {
  const Case c = suiteCaseFile(name);
  return generateGlsl(c, derivePlan(c)).raygen.glsl;
}

TEST(SteppedQueriesGlsl, AnArrayOfQueriesSteppedInTurnByALoopIndex) {
  const std::string g = raygenOf("ray-query/stepped-queries");
  for (const char* needle :
       {"rayQueryEXT rs_queries_0[3];", "rayQueryInitializeEXT(rs_queries_0[0], rs_tlas,",
        "rayQueryInitializeEXT(rs_queries_0[2], rs_tlas,", "uint rs_live_0 = 7u;",
        "#define rs_query rs_queries_0[rs_step_0]", "while (rs_live_0 != 0u) {",
        "for (uint rs_step_0 = 0u; rs_step_0 < 3u; ++rs_step_0) {",
        "if (!rayQueryProceedEXT(rs_query)) {", "rs_live_0 &= ~(1u << rs_step_0);",
        "} else if (rs_step_0 == 2u) {", "rayQueryGenerateIntersectionEXT(rs_query, 9.5);",
        "#define rs_query rs_queries_0[1]", "// after[2]"})
    EXPECT_NE(g.find(needle), std::string::npos) << needle << "\n" << g;
  // Every initialization before the stepping, every after behind it.
  EXPECT_LT(g.find("rayQueryInitializeEXT(rs_queries_0[2]"), g.find("while (rs_live_0"));
  EXPECT_LT(g.find("rs_live_0 &= ~"), g.find("// after[0]"));
  EXPECT_EQ(g.find("uint rs_restarts_0"), std::string::npos);  // no restart: no count
  const SpirvResult r = compileGlsl(g, Stage::Raygen);
  EXPECT_TRUE(r.error.empty()) << r.error << "\n" << g;
}

TEST(SteppedQueriesGlsl, ARestartInitializesTheQueryAgainAndGoesOn) {
  const std::string g = raygenOf("ray-query/restart-mid-traversal");
  for (const char* needle :
       {"uint rs_restarts_0 = 0u;", "#define rs_restarts rs_restarts_0",
        "if (rs_restarts < 8u) {  // restart_query", "rs_restarts += 1u;",
        "rayQueryInitializeEXT(rs_query, rs_tlas, rs_flags, rs_cull_mask, rs_origin, rs_tmin, "
        "rs_direction, rs_tmax);",
        "float rs_tmin = (rayQueryGetIntersectionTEXT(rs_query, false) + 0.5);",
        "uint rs_restarts_0[2];", "rs_restarts_0[1] = 0u;",
        "#define rs_restarts rs_restarts_0[rs_step_0]"})
    EXPECT_NE(g.find(needle), std::string::npos) << needle << "\n" << g;
  // The block ends at a restart: the loop's next proceed.
  const size_t restart = g.find("rayQueryInitializeEXT(rs_query,");
  ASSERT_NE(restart, std::string::npos);
  EXPECT_EQ(g.find("continue;", restart), g.find("continue;\n", restart));
  EXPECT_LT(g.find("continue;", restart), g.find("}", restart));
  const SpirvResult r = compileGlsl(g, Stage::Raygen);
  EXPECT_TRUE(r.error.empty()) << r.error << "\n" << g;
}

}  // namespace
}  // namespace rayspec
