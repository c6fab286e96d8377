// `rayspec merge`: run folders made apart (the shards of one run, or runs on
// several machines of the same device) joined into one, as if one run had
// made it: every case's outcome and folder (bundles, images), and the reports
// written anew.
#pragma once

#include <string>
#include <vector>

#include "report/baseline.h"
#include "report/outcome_json.h"

namespace rayspec {

struct MergeResult {
  SavedRun run;       // info and outcomes (in case-name order)
  std::string error;  // "" when merged; otherwise nothing was written
};

// Reads every folder in `dirs` and joins them into `out` (created; case
// folders are hard-linked where the file system allows, copied otherwise).
// Refuses folders from different devices or model tiers, a case found in two
// folders, and `out` being one of `dirs`. A baseline that is not empty is
// applied to every outcome anew (no re-runs: they happened in the runs).
MergeResult mergeRuns(const std::vector<std::string>& dirs, const std::string& out,
                      const Baseline& baseline, const std::vector<Rule>& catalog);

}  // namespace rayspec
