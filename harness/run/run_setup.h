// What a run needs before its first case, one step each: the case files
// (this shard's), the run's description, the baseline, the device, the cases
// a resumed run already has. Internal to run/ (run_loop.cpp). A step that
// fails says why in its Result; the run then ends before any case runs.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/result.h"
#include "library/case_discovery.h"
#include "report/baseline.h"
#include "report/write_reports.h"
#include "run/device_probe.h"
#include "run/run_options.h"
#include "run/vulkan_adapter.h"
#include "vulkan/icd_environment.h"

namespace rayspec {

// Prints "rayspec run: <why>" and returns kExitSetup.
int setupFailed(const Error& why);

// The case files selected (--cases/--filter or --case), if the options can
// work together.
Result<std::vector<CaseFile>> selectedCaseFiles(const RunOptions& opt);

// Those of files in the shard asked for (--shard, else the CI's variables);
// all of them without one.
Result<std::vector<CaseFile>> thisShard(const RunOptions& opt, std::vector<CaseFile> files);

// The run's description as it starts: time, tier, the rule catalog, marked
// interrupted until the last case is done.
RunInfo startRunInfo(const RunOptions& opt, size_t planned_cases);

// --baseline with its flakes and skips files (an empty baseline without one).
Result<Baseline> loadRunBaseline(const RunOptions& opt);

struct ChosenDevice {
  std::unique_ptr<VulkanAdapter> adapter;  // without isolation: the one device of every case
  bool found = false;                      // a device runs (or saved device results exist)
  bool gpu = false;                        // the device is not this machine's CPU
  // The device as the device side will see it (a live device only): the
  // cases it cannot run are decided before they run (run/case_steps.h).
  std::optional<ProbedDevice> probed;
};
// The device, which must exist before any case runs: saved results
// (--device-results), one in this process (--no-isolation), or one a short
// child process finds. Fills info's device, ICD and validation.
Result<ChosenDevice> chooseDevice(const RunOptions& opt, const std::vector<CaseFile>& files,
                                  const IcdSelection& icd, RunInfo& info);

// --resume: the outcomes the run folder already holds, by case name, if it
// comes from the same kind of run (sets info.started to its start).
Result<std::map<std::string, CaseOutcome>> resumedCases(const RunOptions& opt, RunInfo& info,
                                                        const std::vector<CaseFile>& files);

}  // namespace rayspec
