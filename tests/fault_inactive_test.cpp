// inactive-hides-last-active (Mesa 26.2.6 lavapipe's regression) on the cases
// that isolate it, the model's exact tier as the device: every variant with
// an inactive object before an active one fails, the *-last controls (inactive
// after every active one) are untouched by it and pass.
#include <gtest/gtest.h>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "model/model_engine.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

TEST(InactiveHidesLastActive, FailsEveryIsolatingCaseButTheControls) {
  size_t failed = 0, controls = 0;
  for (const CaseFile& f : findCases(kSuiteCases, "inactive/before-active-*")) {
    ParseResult parsed = loadSuiteCase(f);
    ASSERT_TRUE(parsed.value) << f.name << ": " << parsed.errors.at(0).format();
    const Case& c = *parsed.value;
    const Plan plan = derivePlan(c);
    const Results model = runOnModel(c, plan, ModelOptions{});
    ASSERT_TRUE(model.ok()) << f.name << ": " << model.statusText();
    Results device = perfectDevice(c, model);
    ASSERT_EQ(compareResults(c, plan, device, model).status, Status::Pass) << f.name;
    const FaultResult planted = plantFault("inactive-hides-last-active", c, plan, device, model);
    const Verdict v = compareResults(c, plan, device, model);
    if (endsWith(f.name, "-last")) {
      EXPECT_FALSE(planted.applied) << f.name << ": " << planted.what;
      EXPECT_EQ(v.status, Status::Pass) << f.name << ": " << v.headline();
      ++controls;
    } else {
      EXPECT_TRUE(planted.applied) << f.name << ": " << planted.what;
      EXPECT_EQ(v.status, Status::Fail) << f.name << ": " << planted.what;
      failed += v.status == Status::Fail;
    }
  }
  EXPECT_EQ(controls, 4u * 2u);
  EXPECT_EQ(failed, 4u * 5u);
}

// The same fault on the seed chapter's hand-written cases that show it on
// Mesa 26.2.6 (null-instance: instance 3 lost; nan-x-triangle: primitive 2).
TEST(InactiveHidesLastActive, FailsTheSeedCasesItBreaksOnLavapipe26) {
  for (const char* name :
       {"inactive/null-instance", "inactive/nan-x-triangle", "inactive/nan-min-x-aabb"}) {
    const std::optional<CaseFile> f = suiteCase(name);
    ASSERT_TRUE(f) << name;
    ParseResult parsed = loadSuiteCase(*f);
    ASSERT_TRUE(parsed.value) << name;
    const Plan plan = derivePlan(*parsed.value);
    const Results model = runOnModel(*parsed.value, plan, ModelOptions{});
    Results device = perfectDevice(*parsed.value, model);
    const FaultResult planted =
        plantFault("inactive-hides-last-active", *parsed.value, plan, device, model);
    EXPECT_TRUE(planted.applied) << name;
    EXPECT_EQ(compareResults(*parsed.value, plan, device, model).status, Status::Fail)
        << name << ": " << planted.what;
  }
}

// accel/update-inactive (inactive and degenerate primitives inside an
// update): the perfect device passes; a device whose update ignores it,
// revives the inactive primitives, or left the degenerate ones out for good
// fails each variant. Without an update, update-degenerate-lost changes nothing.
TEST(UpdateInactive, EachFaultOfAnUpdateFailsTheCase) {
  size_t cases = 0;
  for (const CaseFile& f : findCases(kSuiteCases, "accel/update-inactive/*")) {
    ParseResult parsed = loadSuiteCase(f);
    ASSERT_TRUE(parsed.value) << f.name << ": " << parsed.errors.at(0).format();
    const Case& c = *parsed.value;
    const Plan plan = derivePlan(c);
    const Results model = runOnModel(c, plan, ModelOptions{});
    ASSERT_TRUE(model.ok()) << f.name << ": " << model.statusText();
    ASSERT_EQ(compareResults(c, plan, perfectDevice(c, model), model).status, Status::Pass);
    for (const char* fault : {"update-ignored", "inactive-revived", "update-degenerate-lost"}) {
      Results device = perfectDevice(c, model);
      const FaultResult planted = plantFault(fault, c, plan, device, model);
      EXPECT_TRUE(planted.applied) << f.name << " " << fault << ": " << planted.what;
      EXPECT_EQ(compareResults(c, plan, device, model).status, Status::Fail)
          << f.name << " " << fault << ": " << planted.what;
    }
    ++cases;
  }
  EXPECT_EQ(cases, 2u);
  const std::optional<CaseFile> built = suiteCase("inactive/degenerate-triangles");
  ASSERT_TRUE(built);
  ParseResult parsed = loadSuiteCase(*built);
  ASSERT_TRUE(parsed.value);
  const Plan plan = derivePlan(*parsed.value);
  const Results model = runOnModel(*parsed.value, plan, ModelOptions{});
  Results device = perfectDevice(*parsed.value, model);
  EXPECT_FALSE(plantFault("update-degenerate-lost", *parsed.value, plan, device, model).applied);
}

}  // namespace
}  // namespace rayspec
