// What the model expects of a case, ray by ray, for `rayspec show`: each
// ray's compared fields as the model's exact tier records them (whether
// closest-hit or miss ran, where a pipeline runs them), the legal answers of
// an ambiguous ray, and the counters.
#pragma once

#include <string>

#include "case/case.h"
#include "results/results.h"

namespace rayspec {

constexpr size_t kShownRays = 32;  // rays listed at most (the first ones)

// "Model (exact tier) expects:" and a line per ray of the first kShownRays.
std::string describeModelExpectations(const Case& c, const Results& model);

}  // namespace rayspec
