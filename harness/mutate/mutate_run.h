// `rayspec mutate RUN_DIR`: every case of a saved device run (RUN_DIR/<case>/
// device, as `rayspec run --out` or a run-only build writes it) judged
// against the model run here under every generic mutant; the kill matrix in
// OUT/mutate.txt and OUT/mutate.json.
#pragma once

#include <string>

#include "base/result.h"
#include "case/case.h"
#include "library/case_discovery.h"
#include "plan/plan.h"
#include "results/results.h"
#include "run/run_options.h"

namespace rayspec {

struct MutateOptions {
  std::string run_dir;
  std::string out = "rayspec-mutate";
  std::string cases_dir;
  std::string filter = "*";
  unsigned threads = 0;
};

// The variant a saved run's cases ran as (its summary.json's; none there:
// as written), so that each case is judged as it ran (--through
// ray-query*: the traces its query faults break as query loops). The error
// names the file.
Result<RunOptions> savedRunVariant(const std::string& run_dir);

// A case of a saved run as `rayspec mutate` judges it: read from
// `cases_dir`, as `variant` ran it, its plan, the device results the run
// saved (they must be there and ok) and the model's own. The error says
// why it cannot be judged.
struct SavedCase {
  Case c;
  Plan plan;
  Results device, model;
};
Result<SavedCase> loadSavedCase(const CaseFile& f, const std::string& cases_dir,
                                const std::string& run_dir, const RunOptions& variant,
                                unsigned threads);

// 0: every judged case killed the null device and every survivor has a legal
// reason; 1: a hole (or no case judged); kExitSetup-style 2 on bad options.
int runMutate(const MutateOptions& opt);

}  // namespace rayspec
