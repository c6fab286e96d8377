#include "bundle/step_cost_json.h"

namespace rayspec {

nlohmann::json costJson(const StepCosts& costs) {
  nlohmann::json j = nlohmann::json::object();
  for (size_t i = 0; i < kCostSteps; ++i)
    if (costs.seconds[i] > 0) j[costStepName(static_cast<CostStep>(i))] = costs.seconds[i];
  return j;
}

Result<StepCosts> costFromJson(const nlohmann::json& j) {
  StepCosts costs;
  for (const auto& [name, value] : j.items()) {
    CostStep step;
    if (!parseCostStep(name, &step)) return errorMessage("cost: unknown step '" + name + "'");
    costs[step] = value.get<double>();
  }
  return costs;
}

}  // namespace rayspec
