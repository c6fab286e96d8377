// `rayspec prove --device NAME` or `--icd FILE`: the faults only a live
// device shows (fault/rule_faults.h RuleFaults::live: build layouts misread,
// a build past its size) planted in real runs of the case on that device, as
// `rayspec run --case FILE --plant-fault NAME` plants them; the runs' bundles
// go to a temporary folder, removed after.
#pragma once

#include <string>
#include <vector>

#include "base/result.h"
#include "case/case.h"
#include "fault/rule_faults.h"
#include "library/case_discovery.h"
#include "run/run_options.h"

namespace rayspec {

struct LiveProof {
  std::string fault;               // the live fault that proved the claim ("" none)
  std::string headline;            // its verdict, or why the claim was not proved there
  std::vector<std::string> tried;  // "fault: the finding naming the rule, else the worst"
};

// Chooses the device of `run` (its --icd manifests in the environment);
// the error when none can run the cases of `files`.
Result<std::string> startLiveDevice(const RunOptions& run, const std::vector<CaseFile>& files);

// Runs the case on the device without a fault (it must pass), then with each
// of rf.live: proved by the first whose verdict is rf.expect naming rf.rule.
LiveProof proveOnDevice(const RunOptions& run, const Case& c, const RuleFaults& rf);

}  // namespace rayspec
