// One case's outcome from its device and model results: the verdict, the
// difference images (written to dir/diff; none when dir is ""), the failing
// rays' table. Shared by `rayspec run`, `rayspec compare` and `rayspec merge`.
#pragma once

#include <string>

#include "case/case.h"
#include "plan/plan.h"
#include "report/case_outcome.h"
#include "results/results.h"

namespace rayspec {

CaseOutcome judgeCase(const Case& c, const Plan& plan, const Results& device, const Results& model,
                      const std::string& dir);

}  // namespace rayspec
