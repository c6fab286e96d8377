// zero-length-ray-box-missed (a device that takes tmin = tmax as an empty
// interval) on the cases of zero-length rays in boxes, the model's exact tier
// as the device: every ray whose one point lies inside a box and whose
// intersection program reports tmin hits on a correct device and misses under
// the fault, so the case fails; a case without such rays is untouched.
#include <gtest/gtest.h>

#include <algorithm>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "model/model_engine.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

struct Planted {
  FaultResult fault;
  Verdict verdict;
};

Planted plantOn(const std::string& name, const std::string& fault) {
  const std::optional<CaseFile> f = suiteCase(name);
  EXPECT_TRUE(f) << name;
  if (!f) return {};
  ParseResult parsed = loadSuiteCase(*f);
  EXPECT_TRUE(parsed.value) << name;
  if (!parsed.value) return {};
  const Case& c = *parsed.value;
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{});
  Results device = perfectDevice(c, model);
  EXPECT_EQ(compareResults(c, plan, device, model).status, Status::Pass) << name;
  Planted p;
  p.fault = plantFault(fault, c, plan, device, model);
  p.verdict = compareResults(c, plan, device, model);
  return p;
}

bool failsOn(const Verdict& v, const std::string& rule) {
  return std::any_of(v.findings.begin(), v.findings.end(), [&](const Finding& f) {
    return f.status == Status::Fail && findingNames(f, rule);
  });
}

TEST(ZeroLengthRayBoxMissed, FailsTheZeroLengthCasesPipelineAndInline) {
  for (const char* name : {"intersection/zero-length-in-box", "ray-query/zero-length-in-box"}) {
    const Planted p = plantOn(name, "zero-length-ray-box-missed");
    EXPECT_TRUE(p.fault.applied) << name << ": " << p.fault.what;
    EXPECT_EQ(p.verdict.status, Status::Fail) << name << ": " << p.verdict.headline();
    EXPECT_TRUE(failsOn(p.verdict, "R-AABB-CONS")) << name << ": " << p.verdict.headline();
  }
}

TEST(ZeroLengthRayBoxMissed, LeavesACaseWithoutZeroLengthRaysAlone) {
  const Planted p = plantOn("candidates/aabb-closed-interval", "zero-length-ray-box-missed");
  EXPECT_FALSE(p.fault.applied) << p.fault.what;
  EXPECT_EQ(p.verdict.status, Status::Pass) << p.verdict.headline();
}

}  // namespace
}  // namespace rayspec
