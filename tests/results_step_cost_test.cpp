// Step costs: names, the timer, JSON (results/step_cost.h, step_cost_json.h).
#include <gtest/gtest.h>

#include <chrono>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include "results/step_cost.h"
#include "results/step_cost_json.h"

namespace rayspec {
namespace {

TEST(StepCost, EveryStepHasItsOwnNameThatReadsBack) {
  std::set<std::string> names;
  for (size_t i = 0; i < kCostSteps; ++i) {
    const CostStep s = static_cast<CostStep>(i);
    const std::string name = costStepName(s);
    EXPECT_NE(name, "?");
    EXPECT_TRUE(names.insert(name).second) << name << " twice";
    CostStep back;
    ASSERT_TRUE(parseCostStep(name, &back)) << name;
    EXPECT_EQ(back, s);
  }
  CostStep out;
  EXPECT_FALSE(parseCostStep("nosuchstep", &out));
}

TEST(StepCost, TimerAddsOnceAndSumsAdd) {
  StepCosts c;
  {
    StepTimer t(c, CostStep::Trace);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const double s = t.stop();
    EXPECT_GE(s, 0.004);
    EXPECT_EQ(c[CostStep::Trace], s);
  }  // the destructor adds nothing after stop()
  const double trace = c[CostStep::Trace];
  EXPECT_EQ(c.total(), trace);
  { StepTimer t(c, CostStep::Trace); }
  EXPECT_GE(c[CostStep::Trace], trace);
  c.add(CostStep::Parse, 1.0);
  StepCosts d = c;
  d += c;
  EXPECT_DOUBLE_EQ(d.total(), 2 * c.total());
  CaseCost cc;
  cc[CostSide::Device] = c;
  cc[CostSide::Parent].add(CostStep::Reports, 0.5);
  EXPECT_DOUBLE_EQ(cc.total(), c.total() + 0.5);
}

TEST(StepCost, JsonKeepsTheStepsThatTookTimeAndRefusesUnknownOnes) {
  StepCosts c;
  c.add(CostStep::SpirvCompile, 0.25);
  c.add(CostStep::ModelTrace, 1.5);
  const nlohmann::json j = costJson(c);
  EXPECT_EQ(j.size(), 2u);
  EXPECT_EQ(j["spirv_compile"], 0.25);
  const Result<StepCosts> back = costFromJson(j);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->seconds, c.seconds);
  const Result<StepCosts> unknown = costFromJson(nlohmann::json{{"warp_drive", 1.0}});
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error().message, "cost: unknown step 'warp_drive'");
}

}  // namespace
}  // namespace rayspec
