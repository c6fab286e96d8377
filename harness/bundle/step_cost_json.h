// StepCosts as JSON: {"spirv_compile": 0.012, ...}, the steps that took time.
#pragma once

#include <nlohmann/json.hpp>

#include "base/result.h"
#include "results/step_cost.h"

namespace rayspec {

nlohmann::json costJson(const StepCosts& costs);
// The costs, or the error naming an unknown step. A value that is no number
// is nlohmann-json's exception: the caller reads JSON, and catches its
// exceptions where it does.
Result<StepCosts> costFromJson(const nlohmann::json& j);

}  // namespace rayspec
