// The per-ray table of a failing case: for the first rays of each failing
// finding, the kept fields and stage run counts, device against model.
#pragma once

#include <vector>

#include "compare/verdict.h"
#include "plan/plan.h"
#include "report/case_outcome.h"
#include "results/results.h"

namespace rayspec {

std::vector<RayRow> failingRays(const Verdict& v, const Plan& plan, const Results& device,
                                const Results& model);

}  // namespace rayspec
