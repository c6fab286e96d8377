// ray_query statements as GLSL (glsl/emit_query.h): one rayQueryEXT per
// nesting depth, the getters through the macro rs_query, and SPIR-V that
// compiles.
#include <gtest/gtest.h>

#include <string>

#include "glsl/generate_glsl.h"
#include "spirv/compile_glsl.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

size_t occurrences(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

TEST(QueryStatementGlsl, NestedQueriesHaveAVariableEachAndCompile) {
  const Case c = suiteCaseFile("ray-query/two-queries");
  const std::string g = generateGlsl(c, derivePlan(c)).raygen.glsl;
  for (const char* needle :
       {"#extension GL_EXT_ray_query : require", "#define RS_USE_TLAS", "rayQueryEXT rs_query_0;",
        "rayQueryEXT rs_query_1;", "while (rayQueryProceedEXT(rs_query_0))",
        "while (rayQueryProceedEXT(rs_query_1))", "rayQueryConfirmIntersectionEXT(rs_query);",
        "rayQueryGetIntersectionTEXT(rs_query, true)",
        "rayQueryGetIntersectionTEXT(rs_query, false)"})
    EXPECT_NE(g.find(needle), std::string::npos) << needle;
  // rs_query names the inner query inside it and the outer one again after.
  const size_t inner = g.find("#define rs_query rs_query_1");
  const size_t back = g.find("#define rs_query rs_query_0", inner);
  ASSERT_NE(inner, std::string::npos);
  ASSERT_NE(back, std::string::npos);
  EXPECT_LT(g.find("while (rayQueryProceedEXT(rs_query_1))"), back);
  EXPECT_EQ(occurrences(g, "#undef rs_query"), 3u) << g;
  EXPECT_EQ(g.find("traceRayEXT("), std::string::npos);
  const SpirvResult r = compileGlsl(g, Stage::Raygen);
  EXPECT_TRUE(r.error.empty()) << r.error << "\n" << g;
}

TEST(QueryStatementGlsl, FieldsDefaultToTheLaunchRayAndCommitStatementsCompile) {
  const Case c = suiteCaseFile("ray-query/query-first-hit");
  const std::string g = generateGlsl(c, derivePlan(c)).raygen.glsl;
  for (const char* needle :
       {"uint rs_flags = rs_ray.flags;", "vec3 rs_origin = rs_ray.origin;",
        "rayQueryInitializeEXT(rs_query_0, rs_tlas, rs_flags, rs_cull_mask, rs_origin, rs_tmin, "
        "rs_direction, rs_tmax);",
        "rayQueryGenerateIntersectionEXT(rs_query, 15.0);", "#define RS_USE_RAYS"})
    EXPECT_NE(g.find(needle), std::string::npos) << needle << "\n" << g;
  const SpirvResult r = compileGlsl(g, Stage::Raygen);
  EXPECT_TRUE(r.error.empty()) << r.error;
  const Case t = suiteCaseFile("ray-query/terminate-middle");
  const std::string tg = generateGlsl(t, derivePlan(t)).raygen.glsl;
  EXPECT_NE(tg.find("rayQueryTerminateEXT(rs_query);"), std::string::npos);
  EXPECT_TRUE(compileGlsl(tg, Stage::Raygen).error.empty());
}

}  // namespace
}  // namespace rayspec
