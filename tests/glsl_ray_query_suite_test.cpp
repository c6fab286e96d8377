// Every case of cases/ its ray query forms can express (case/
// ray_query_inlining.h) compiles in both: raygen hosting every trace, nested
// levels included (--through ray-query), and each closest-hit and miss that
// traces hosting its own (--through ray-query-in-hit). What a device is
// handed by those paths, checked here before any device runs it.
#include <gtest/gtest.h>

#include <iostream>
#include <map>
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
    const SpirvResult r = compileGlsl(sh->glsl, sh->stage, sh->compute);
    EXPECT_TRUE(r.error.empty()) << name << " " << sh->name << ":\n" << r.error;
  }
  return hosts;
}

// The reasons a form refuses cases, counted (printed: docs/ray-queries.md
// lists them, references/runs/ keeps their counts).
void tally(std::map<std::string, size_t>& reasons, const std::string& why) {
  std::string key = why;
  if (const size_t digits = key.find(" copies of"); digits != std::string::npos)
    key = key.substr(0, digits);  // the copy count's detail differs per case
  ++reasons[key];
}

void print(const char* form, const std::map<std::string, size_t>& reasons) {
  for (const auto& [why, n] : reasons)
    std::cout << form << (why.empty() ? " run, " : " not run, ") << n << ": " << why << "\n";
}

TEST(RayQuerySuiteGlsl, EveryExpressibleCaseCompilesInBothForms) {
  std::set<std::string> seen;
  std::map<std::string, size_t> raygen_reasons, hit_reasons;
  size_t in_raygen = 0, in_hit = 0, nested = 0;
  for (const CaseFile& f : suiteCases()) {
    const ParseResult parsed = loadSuiteCase(f);
    if (!parsed.value) continue;
    Case c = *parsed.value;
    tally(raygen_reasons, rayQueryObstacle(c));
    tally(hit_reasons, rayQueryInHitObstacle(c));
    if (c.pipeline.ray_query || c.pipeline.ray_query_in_hit) continue;
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
  print("ray-query", raygen_reasons);
  print("ray-query-in-hit", hit_reasons);
  // Measured 2026-11-27: the cases that trace from closest-hit or miss are
  // in both counts.
  EXPECT_GT(in_raygen, 550u);
  EXPECT_GT(nested, 20u);
  EXPECT_GT(in_hit, 20u);
}

}  // namespace
}  // namespace rayspec
