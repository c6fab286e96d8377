// A case as a run's variant runs it (--permute, --move, --through, in that
// order), and a run folder's variant (RunInfo::variant, runVariant) read back
// into those options: `rayspec merge` judges a shard's bundles by the case as
// the shard ran it.
#pragma once

#include <optional>
#include <string>

#include "base/result.h"
#include "case/case.h"
#include "report/case_outcome.h"
#include "run/run_options.h"

namespace rayspec {

// The case permuted, moved and sent through a feature path as `opt` asks;
// or, in place of it, the NotSupported outcome of a case the variant cannot
// run (a motion it cannot make exactly, a path it cannot take), saying why.
struct CaseAsRun {
  std::optional<Case> runs;
  std::optional<CaseOutcome> not_run;
};
CaseAsRun caseAsRun(const Case& parsed, const RunOptions& opt);

// Sets opt.through, opt.permute and opt.move from a variant as runVariant
// writes it ("" for none, "through update; permute 7; move -y,x,z"). The
// error: text runVariant does not write, saying which part.
Result<void> variantOptions(const std::string& variant, RunOptions& opt);

}  // namespace rayspec
