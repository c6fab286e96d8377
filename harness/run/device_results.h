// Judging a device run saved elsewhere: `rayspec run --device-results DIR`
// runs the model here and, in place of a device, reads each case's device
// bundle DIR/<case>/device/ (bundle/results_io.h; what a run-only build's
// `rayspec run --out DIR` writes), then judges exactly as a live run would:
// planted faults apply to the loaded results, crashes and timeouts saved
// there are this case's Crash and Timeout.
//   no bundle           NotSupported: the case did not run there (filtered
//                       out, or that run stopped before it; a case whose
//                       process died there has a bundle saying Crash or
//                       Timeout). Nothing was compared, so never a pass.
//   another case's, or  the harness's error (CaseError): the bundle names
//   one of a changed    another case, or records a case hash (contentHash of
//   case file           the case's text, --permute's seed mixed in) other
//                       than the case's here, or none (an older rayspec).
#pragma once

#include <string>
#include <vector>

#include "base/result.h"
#include "library/case_discovery.h"
#include "run/backend.h"
#include "run/run_options.h"

namespace rayspec {

// A device that "runs" a case by reading its saved bundle. A bundle that does
// not read, or does not belong to the case, is an ErrorKind::Harness error.
class SavedDevice : public Backend {
 public:
  explicit SavedDevice(std::string dir) : dir_(std::move(dir)) {}
  std::string name() const override { return "vulkan"; }
  std::string description() const override { return "device results saved in " + dir_; }
  Result<Results> run(const Case& c, const Plan& plan) override;
  std::vector<std::string> close() override { return {}; }

 private:
  std::string dir_;
};

// The bundle in `dir` (a case's device or model folder of a saved run) read
// back as the results of case `c`: the bundle must be that case's (its
// name), of the case as it is here (case_hash: the case's text, with
// --permute's seed and --move's motion mixed in; none: an older rayspec), and
// hold only the counters the case keeps. The error (ErrorKind::Harness)
// names dir/results.json and what differs.
Result<Results> readCaseBundle(const std::string& dir, const Case& c, const Plan& plan);
// Those checks of a bundle read from `dir` already (rayspec compare).
Result<void> checkCaseBundle(const Results& r, const std::string& dir, const Case& c,
                             const Plan& plan);

// DIR/<case>/device.
std::string savedBundleDir(const std::string& dir, const std::string& case_name);

// Why --device-results cannot work with the other options, an
// ErrorKind::Input error (none when it can, or when it is not given): no
// model in this build, --no-model, --no-device, --device, a Vulkan error
// fault (they need a live device), DIR not a folder, DIR the --out folder
// (the run would remove what it reads).
Result<void> deviceResultsError(const RunOptions& opt);

// The devices these cases' saved bundles ran on, each once ("A" or "A, B");
// "" when none of them has a bundle naming one.
std::string savedDevices(const std::string& dir, const std::vector<CaseFile>& cases);

}  // namespace rayspec
