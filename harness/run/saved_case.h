// A case of a saved run folder judged anew from its bundles, as `rayspec run
// --device-results` judges a saved device run: the case looked up by name
// under the cases folder, made as the run's variant made it
// (run/case_as_run.h), each bundle read as that case's (readCaseBundle: its
// name, its case_hash, its counters) and the sides judged (judgeSides).
// `rayspec merge` takes every verdict from here, never a shard's
// summary.json on its word (report/merge_runs.h):
//   both bundles    judged, device against model
//   one bundle      that side's own status (a --no-model or --no-device run,
//                   or the model's crash): never a pass
//   none            the case did not run there (skipped, a case-file error, a
//                   case the variant does not run): the summary's word is
//                   kept, unless it says the case passed
//   summary.json    a device other than the one the case's bundle ran on is
//   says otherwise  a refusal of the shard; a status other than its bundles
//                   give: the bundles' verdict, with a finding (rule "merge",
//                   QualityWarning) quoting what the summary said
// A flake needs its re-run's bundles (<case>/rerun), of the same sides, that
// judge cleanly and give another result.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "base/result.h"
#include "library/case_discovery.h"
#include "report/case_outcome.h"
#include "report/merge_runs.h"
#include "run/run_options.h"

namespace rayspec {

// The bundles a case folder holds: folder/device/results.json and
// folder/model/results.json.
struct SavedSides {
  bool device = false, model = false;
  bool operator==(const SavedSides&) const = default;
};
SavedSides savedSides(const std::string& folder);

// The cases of a folder by name, listed once (sweeps expanded): a merge
// looks up every case of its shards.
struct CaseIndex {
  std::string dir;
  std::map<std::string, CaseFile> by_name;
};
CaseIndex indexCases(const std::string& cases_dir);

// The case `name` as `variant` runs it, its file from `cases`; the error
// (ErrorKind::Harness): there is none here, it does not parse here, or the
// variant does not run it.
Result<Case> caseHere(const std::string& name, const RunOptions& variant, const CaseIndex& cases);

// The case `name` judged from the bundles in `folder` (<run>/<case>, or its
// rerun subfolder), the case made as `variant` (its through, permute and
// move) makes it; nullopt where the folder holds no bundle. The error
// (ErrorKind::Harness): the bundles cannot be judged, saying why (no such
// case here, a case file that does not parse here, one the variant does not
// run, a bundle that does not read or is not this case's).
Result<std::optional<CaseOutcome>> judgeSavedCase(const std::string& folder,
                                                  const std::string& name,
                                                  const RunOptions& variant,
                                                  const CaseIndex& cases);

// The judge of `rayspec merge`, its cases looked up under cases_dir.
ShardCaseJudge shardCaseJudge(const std::string& cases_dir);

}  // namespace rayspec
