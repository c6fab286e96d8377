// A case's outcome as JSON and back: summary.json holds one per case, and a
// run folder read back (`--resume`, `rayspec merge`) is made of them.
#pragma once

#include "base/result.h"

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/case_outcome.h"
#include "report/write_reports.h"

namespace rayspec {

const char* baselineMatchName(BaselineMatch m);  // "" for None, "expected", "unexpected_pass", ...

nlohmann::json outcomeJson(const CaseOutcome& outcome);
// The outcome, or the error naming the case and the field that is missing or
// wrong.
Result<CaseOutcome> outcomeFromJson(const nlohmann::json& j);

// A run folder's summary.json read back: what ran, and every case's outcome
// in the order they ran.
struct SavedRun {
  RunInfo info;
  std::vector<CaseOutcome> outcomes;
};
// The error: the folder has no readable summary.json, or names the case and
// field that could not be read. A run marked interrupted takes its cases
// from its journal (report/case_journal.h) where it has one.
Result<SavedRun> readSavedRun(const std::string& dir);
// The most bytes a summary.json may hold (about 2.6 kB a case: 1.9 MB for
// 734 cases).
constexpr uint64_t kMaxSummaryJsonBytes = 256ull << 20;

}  // namespace rayspec
