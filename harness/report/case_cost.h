// Where a case's time went (results/step_cost.h), per case and for a run:
//   <out>/<case>/cost.json  {"case", "seconds": the case's wall time,
//                            "accounted": the sum of every step,
//                            "parent" / "model" / "device": {step: seconds}}
//   summary.json "cost"     the same summed over the run's cases, and "by_step"
//                           (every step, every side together)
//   summary.txt             a table of the run's steps, the costliest first
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/result.h"
#include "report/case_outcome.h"

namespace rayspec {

nlohmann::json caseCostJson(const CaseCost& cost);
// The cost, or the error naming an unknown side or step (a value of the
// wrong type: nlohmann-json's exception, for the reader of the JSON).
Result<CaseCost> caseCostFromJson(const nlohmann::json& j);

// cost.json of one case; the error: ErrorKind::Harness, the file not written,
// or ErrorKind::Input, the case's name not UTF-8 (report/json_text.h).
Result<void> writeCaseCost(const CaseOutcome& outcome, const std::string& path);

// Every case's cost summed.
CaseCost runCost(const std::vector<CaseOutcome>& outcomes);
nlohmann::json runCostJson(const std::vector<CaseOutcome>& outcomes);
// The table of summary.txt: one line per side and step that took time.
std::string runCostText(const std::vector<CaseOutcome>& outcomes);

}  // namespace rayspec
