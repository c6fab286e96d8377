// StepCosts as JSON: {"spirv_compile": 0.012, ...}, the steps that took time.
#pragma once

#include <nlohmann/json.hpp>

#include "results/step_cost.h"

namespace rayspec {

nlohmann::json costJson(const StepCosts& costs);
// Throws std::runtime_error naming an unknown step.
StepCosts costFromJson(const nlohmann::json& j);

}  // namespace rayspec
