// R-AHIT-DUP: a device that runs an accumulating any-hit twice for a primitive
// (legal without no_duplicate_any_hit) is not failed; a case whose results
// depend on it and that does not claim the rule is diagnosed, not judged
// (compare/any_hit_repeat_verdict.h, model/any_hit_repeat.h).
#include <gtest/gtest.h>

#include <algorithm>

#include "compare/compare_results.h"
#include "model/model_engine.h"
#include "plan/plan.h"
#include "results/record_layout.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

Case suiteVariant(const std::string& name) {
  const std::optional<CaseFile> f = suiteCase(name);
  if (!f) {
    ADD_FAILURE() << "no case " << name;
    return Case{};
  }
  ParseResult parsed = loadSuiteCase(*f);
  EXPECT_TRUE(parsed.value.has_value()) << name;
  return parsed.value ? *parsed.value : Case{};
}

// The model's run as a device that repeats every any-hit it may.
Results repeatingDevice(const Case& c, const Plan& plan) {
  ModelOptions o;
  o.any_hit_repeat = AnyHitRepeat::All;
  return runOnModel(c, plan, o);
}

bool hasFinding(const Verdict& v, Status s, const std::string& rule, const std::string& text) {
  return std::any_of(v.findings.begin(), v.findings.end(), [&](const Finding& f) {
    return f.status == s && f.rule == rule && f.message.find(text) != std::string::npos;
  });
}

TEST(AnyHitRepeat, TheModelFindsWhatRepetitionChanges) {
  const Case c = suiteVariant("anyhit/accumulate/triangles-allowed");
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_TRUE(model.ok()) << model.statusText();
  ASSERT_EQ(model.repeat_dependent.size(), 64u) << "every ray crosses a primitive";
  const int value = recordFieldIndex("value"), hit = recordFieldIndex("hit");
  for (const RepeatDependentRay& d : model.repeat_dependent) {
    EXPECT_TRUE((d.fields >> value) & 1u) << "ray " << d.ray;
    EXPECT_FALSE((d.fields >> hit) & 1u) << "every candidate is ignored however often";
  }
  // Under no_duplicate_any_hit any-hit runs once: nothing depends on repeats.
  const Case flagged = suiteVariant("anyhit/accumulate/triangles-forbidden");
  const Results once = runOnModel(flagged, derivePlan(flagged), ModelOptions{});
  EXPECT_TRUE(once.repeat_dependent.empty());
  EXPECT_TRUE(once.repeat_counters.empty());
}

TEST(AnyHitRepeat, ACorrectDeviceThatRepeatsPasses) {
  for (const char* name :
       {"anyhit/accumulate/triangles-allowed", "anyhit/accumulate/aabbs-allowed"}) {
    const Case c = suiteVariant(name);
    const Plan plan = derivePlan(c);
    const Results model = runOnModel(c, plan, ModelOptions{});
    const Results device = repeatingDevice(c, plan);
    ASSERT_FALSE(sameOutput(device, model)) << name << ": the repeats change nothing";
    const Verdict v = compareResults(c, plan, device, model);
    EXPECT_EQ(v.status, Status::Pass) << name << ": " << v.headline();
    EXPECT_TRUE(hasFinding(v, Status::Pass, "R-AHIT-DUP", "left out")) << v.headline();
    // The exact comparison this replaces failed that correct device.
    Results exact_model = model;
    exact_model.repeat_dependent.clear();
    exact_model.repeat_counters.clear();
    EXPECT_EQ(compareResults(c, plan, device, exact_model).status, Status::Fail) << name;
  }
}

TEST(AnyHitRepeat, ACaseThatDependsOnRepetitionWithoutClaimingItIsDiagnosed) {
  Case c = suiteVariant("anyhit/accumulate/triangles-allowed");
  c.rules.erase(std::remove(c.rules.begin(), c.rules.end(), "R-AHIT-DUP"), c.rules.end());
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{});
  const Verdict v = compareResults(c, plan, model, model);
  EXPECT_EQ(v.status, Status::CaseError) << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::CaseError, "R-AHIT-DUP", "not portable")) << v.headline();
}

TEST(AnyHitRepeat, AWrongSumUnderTheFlagFails) {
  const Case c = suiteVariant("anyhit/accumulate/triangles-forbidden");
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{});
  Results device = model;
  const uint32_t value = findRecordField("value")->offset;
  device.records[value] += 1;  // ray 0's sum is one term off
  const Verdict v = compareResults(c, plan, device, model);
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
}

}  // namespace
}  // namespace rayspec
