// The live-device faults of a claim planted in real runs of the case.
#include "mutate/prove_live.h"

#include <stdlib.h>

#include <filesystem>

#include "run/cache_dir.h"
#include "run/case_steps.h"
#include "run/run_setup.h"
#include "vulkan/icd_environment.h"

namespace rayspec {
namespace {

// One run of the case on the device, `fault` planted ("" none), its bundles
// in a temporary folder removed after.
CaseOutcome runOnDevice(RunOptions run, const Case& c, const std::string& fault) {
  std::string dir = (std::filesystem::temp_directory_path() / "rayspec-prove-XXXXXX").string();
  if (!mkdtemp(dir.data()))
    return caseErrorOutcome(c.name, c.rules, "harness", "no temporary folder for the run");
  run.out = dir;
  run.plant_fault = fault;
  run.plant_fault_in = "*";
  const CaseRunner runner(run, nullptr, nullptr);
  bool interrupted = false;
  CaseOutcome out = guardCase(c.name, c.rules, [&] { return runner.run(c, &interrupted); });
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  return out;
}

}  // namespace

Result<std::string> startLiveDevice(const RunOptions& run, const std::vector<CaseFile>& files) {
  const IcdSelection icd = useIcdFiles(run.icd_files);
  if (!icd.error.empty()) return errorMessage(icd.error);
  RunInfo info;
  RAYSPEC_TRY(const ChosenDevice chosen, chooseDevice(run, files, icd, info));
  if (!run.cache_dir.empty()) RAYSPEC_TRY_VOID(useCacheDir(run.cache_dir));
  return info.device;
}

LiveProof proveOnDevice(const RunOptions& run, const Case& c, const RuleFaults& rf) {
  LiveProof p;
  const CaseOutcome clean = runOnDevice(run, c, "");
  if (clean.status != Status::Pass) {
    p.headline = "the device does not pass the case without a fault: " + clean.headline;
    return p;
  }
  for (const std::string& fault : rf.live) {
    const CaseOutcome o = runOnDevice(run, c, fault);
    // The finding naming the rule where one does, else the verdict's worst.
    const std::string named = claimLine(o.verdict, rf.rule);
    p.tried.push_back(fault + ": " +
                      (named.empty() ? o.headline.substr(0, o.headline.find("; also ")) : named));
    if (o.status == rf.expect && !named.empty()) {
      p.fault = fault;
      p.headline = o.headline;
      return p;
    }
  }
  p.headline = std::string("no live fault gives ") + statusName(rf.expect) + " naming " + rf.rule;
  return p;
}

}  // namespace rayspec
