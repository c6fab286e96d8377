// `rayspec merge`: run folders made apart (the shards of one run, or runs on
// several machines of the same device) joined into one, as if one run had
// made it: every case's outcome and folder (bundles, images), and the reports
// written anew.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "report/baseline.h"
#include "report/outcome_json.h"

namespace rayspec {

// How a merge learns each case's result, never from a shard's summary.json
// on its word (run/saved_case.h judges it anew from the case's bundles):
// the case `claimed` (as the summary.json of `shard`, whose run is `info`,
// says it ended) as its bundles show it; with `rerun`, its re-run's
// (<case>/rerun, which a baseline run makes of an unexpected failure), or
// nullopt where the shard holds no re-run to go by. The error: the shard
// refused (its summary.json says what its bundles do not).
using ShardCaseJudge = std::function<Result<std::optional<CaseOutcome>>(
    const std::string& shard, const RunInfo& info, const CaseOutcome& claimed, bool rerun)>;

// Reads every folder in `dirs` and joins them into `out` (created; case
// folders are hard-linked where the file system allows, copied otherwise).
// Refuses folders from different devices or model tiers, a case found in two
// folders, and `out` being one of `dirs`. Every case is as `judge` finds it;
// the baseline (empty: none, each case judged by its status alone) is
// applied to every case anew, and an unexpected failure is a flake only
// where its re-run in the shard gave another result (a merge runs nothing).
// The merged run: its info and outcomes (in case-name order). The error: a
// refusal or a folder that cannot be read, before anything is written; or a
// case folder not copied or the reports not written (ErrorKind::Harness).
Result<SavedRun> mergeRuns(const std::vector<std::string>& dirs, const std::string& out,
                           const Baseline& baseline, const std::vector<Rule>& catalog,
                           const ShardCaseJudge& judge);

}  // namespace rayspec
