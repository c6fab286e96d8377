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

// Reads every folder in `dirs` and joins them into `out` (created; case
// folders are hard-linked where the file system allows, copied otherwise).
// Refuses folders from different devices or model tiers, a case found in two
// folders, and `out` being one of `dirs`. A baseline that is not empty is
// applied to every outcome anew (no re-runs: they happened in the runs).
// The merged run: its info and outcomes (in case-name order). The error: a
// refusal or a folder that cannot be read, before anything is written; or a
// case folder not copied or the reports not written (ErrorKind::Harness).
Result<SavedRun> mergeRuns(const std::vector<std::string>& dirs, const std::string& out,
                           const Baseline& baseline, const std::vector<Rule>& catalog);

}  // namespace rayspec
