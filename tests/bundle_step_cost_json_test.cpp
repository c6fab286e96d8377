// Step costs as JSON (bundle/step_cost_json.h).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "bundle/step_cost_json.h"

namespace rayspec {
namespace {

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
