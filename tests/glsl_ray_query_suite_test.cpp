// Every case of cases/ its ray query forms can express (case/
// ray_query_inlining.h) compiles in both: raygen hosting every trace, nested
// levels included (--through ray-query), and each closest-hit and miss that
// traces hosting its own (--through ray-query-in-hit). What a device is
// handed by those paths, checked here before any device runs it.
#include <gtest/gtest.h>

#include <set>

#include "case/ray_query_inlining.h"
#include "glsl/generate_glsl.h"
#include "plan/plan.h"
#include "spirv/compile_glsl.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

// Compiles the stages that host inlined programs (their GLSL names a ray
// query); returns how many compiled.
size_t compileHosts(const std::string& name, const Case& c, std::set<std::string>& seen) {
  size_t hosts = 0;
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  for (const GeneratedShader* sh : everyStage(g)) {
    if (sh->glsl.find("rayQueryEXT rs_rq;") == std::string::npos) continue;
    if (!seen.insert(std::to_string(int(sh->stage)) + sh->glsl).second) continue;
    ++hosts;
    const SpirvResult r = compileGlsl(sh->glsl, sh->stage);
    EXPECT_TRUE(r.error.empty()) << name << " " << sh->name << ":\n" << r.error;
  }
  return hosts;
}

TEST(RayQuerySuiteGlsl, EveryExpressibleCaseCompilesInBothForms) {
  std::set<std::string> seen;
  size_t in_raygen = 0, in_hit = 0, nested = 0;
  for (const CaseFile& f : suiteCases()) {
    const ParseResult parsed = loadSuiteCase(f);
    if (!parsed.value || parsed.value->pipeline.ray_query) continue;
    Case c = *parsed.value;
    if (rayQueryObstacle(c).empty()) {
      c.pipeline.ray_query = true;
      in_raygen += compileHosts(f.name, c, seen) > 0;
      nested += hitOrMissTraces(c.pipeline);
      c.pipeline.ray_query = false;
    }
    if (rayQueryInHitObstacle(c).empty()) {
      c.pipeline.ray_query_in_hit = true;
      in_hit += compileHosts(f.name, c, seen) > 0;
    }
  }
  // Measured 2026-11-27: the cases that trace from closest-hit or miss are
  // in both counts.
  EXPECT_GT(in_raygen, 550u);
  EXPECT_GT(nested, 20u);
  EXPECT_GT(in_hit, 20u);
}

}  // namespace
}  // namespace rayspec
