// incoming-flags-with-pipeline-skip (gl_IncomingRayFlagsEXT holding the
// pipeline's SKIP_TRIANGLES / SKIP_AABBS, which the specification forbids) on
// builtins/incoming-flags-pipeline-skip, the model's exact tier as the device:
// every variant whose pipeline has a skip flag fails, R-BUILTIN on the flags
// closest-hit and miss record (the field incoming_ray_flags; intersection and
// any-hit record theirs in value and value1); the variants without one are
// untouched.
#include <gtest/gtest.h>

#include "planted_suite_case.h"

namespace rayspec {
namespace {

// Whether a failing finding of rule `rule` names the per-ray field `field`.
bool failsField(const Verdict& v, const std::string& rule, const std::string& field) {
  for (const Finding& f : v.findings)
    if (f.status == Status::Fail && labelNames(f, rule) &&
        f.message.find("'" + field + "'") != std::string::npos)
      return true;
  return false;
}

TEST(IncomingFlagsWithPipelineSkip, FailsEveryVariantWithAPipelineSkipFlag) {
  size_t failed = 0, untouched = 0;
  for (const CaseFile& f : findCases(kSuiteCases, "builtins/incoming-flags-pipeline-skip/*")) {
    const std::optional<SuiteModelRun> run = suiteModelRun(f);
    ASSERT_TRUE(run);
    const auto [planted, v] = plantOnModel(*run, "incoming-flags-with-pipeline-skip");
    if (f.name.find("/none-") != std::string::npos) {
      EXPECT_FALSE(planted.applied) << f.name << ": " << planted.what;
      EXPECT_EQ(v.status, Status::Pass) << f.name << ": " << v.headline();
      ++untouched;
      continue;
    }
    EXPECT_TRUE(planted.applied) << f.name << ": " << planted.what;
    EXPECT_EQ(v.status, Status::Fail) << f.name << ": " << v.headline();
    EXPECT_TRUE(failsField(v, "R-BUILTIN", "incoming_ray_flags")) << f.name << ": " << v.headline();
    failed += v.status == Status::Fail;
  }
  EXPECT_EQ(untouched, 5u);
  EXPECT_EQ(failed, 2u * 5u);
}

}  // namespace
}  // namespace rayspec
