// zero-length-ray-box-missed (a device that takes tmin = tmax as an empty
// interval) on the cases of zero-length rays in boxes, the model's exact tier
// as the device: every ray whose one point lies inside a box and whose
// intersection program reports tmin hits on a correct device and misses under
// the fault, so the case fails; a case without such rays is untouched.
#include <gtest/gtest.h>

#include <algorithm>

#include "planted_suite_case.h"

namespace rayspec {
namespace {

bool failsOn(const Verdict& v, const std::string& rule) {
  return std::any_of(v.findings.begin(), v.findings.end(), [&](const Finding& f) {
    return f.status == Status::Fail && findingNames(f, rule);
  });
}

TEST(ZeroLengthRayBoxMissed, FailsTheZeroLengthCasesPipelineAndInline) {
  for (const char* name : {"intersection/zero-length-in-box", "ray-query/zero-length-in-box"}) {
    const PlantedVerdict p = plantOnSuiteCase(name, "zero-length-ray-box-missed");
    EXPECT_TRUE(p.fault.applied) << name << ": " << p.fault.what;
    EXPECT_EQ(p.verdict.status, Status::Fail) << name << ": " << p.verdict.headline();
    EXPECT_TRUE(failsOn(p.verdict, "R-AABB-CONS")) << name << ": " << p.verdict.headline();
  }
}

TEST(ZeroLengthRayBoxMissed, LeavesACaseWithoutZeroLengthRaysAlone) {
  const PlantedVerdict p =
      plantOnSuiteCase("candidates/aabb-closed-interval", "zero-length-ray-box-missed");
  EXPECT_FALSE(p.fault.applied) << p.fault.what;
  EXPECT_EQ(p.verdict.status, Status::Pass) << p.verdict.headline();
}

}  // namespace
}  // namespace rayspec
