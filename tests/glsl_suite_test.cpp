// Every stage of every case in cases/ (sweeps expanded) compiles to SPIR-V that
// Debian 12's SPIRV-Tools accepts and that passes the checks newer validators
// add (spirv/builtin_inputs.h): what the device side will hand a driver.
#include <gtest/gtest.h>

#include <algorithm>

#include <set>

#include "glsl/generate_glsl.h"
#include "plan/plan.h"
#include "spirv/compile_glsl.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

TEST(GenerateGlslSuite, EveryStageOfEveryCaseIsValidSpirv) {
  std::set<std::string> seen;  // GLSL texts already compiled (sweeps repeat stages)
  size_t cases = 0, modules = 0;
  for (const CaseFile& f : suiteCases()) {
    ParseResult parsed = loadSuiteCase(f);
    if (!parsed.value) continue;  // the case's own test reports its errors
    ++cases;
    const GeneratedPipeline g = generateGlsl(*parsed.value, derivePlan(*parsed.value));
    for (const GeneratedShader* sh : everyStage(g)) {
      if (!seen.insert(std::to_string(int(sh->stage)) + sh->glsl).second) continue;
      ++modules;
      SpirvResult r = compileGlsl(sh->glsl, sh->stage, sh->compute);
      // A shader the case expects the compiler to reject (expect_rejected) must not compile.
      const auto& rejections = parsed.value->expected_rejections;
      const bool rejected =
          std::any_of(rejections.begin(), rejections.end(),
                      [&](const ExpectedRejection& e) { return e.shader == sh->name; });
      EXPECT_EQ(r.error.empty(), !rejected) << f.name << " " << sh->name << ":\n" << r.error;
    }
  }
  EXPECT_GT(cases, 400u);
  EXPECT_GT(modules, 1000u);
}

}  // namespace
}  // namespace rayspec
