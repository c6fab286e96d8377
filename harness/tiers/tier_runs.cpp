// Tier runs: one `rayspec run` per tier and glob, and their bundles read back.
#include "tiers/tier_runs.h"

#include <cstdio>
#include <fstream>

#include "base/visible_text.h"
#include "bundle/results_io.h"
#include "library/case_discovery.h"
#include "run/run_loop.h"

namespace rayspec {

std::string tierRunDir(const std::string& out, const std::string& tier) {
  return out + "/" + tier;
}

std::vector<std::string> tierRunCases(const RunOptions& run,
                                      const std::vector<std::string>& filters) {
  std::vector<std::string> names;
  for (const CaseFile& f : findCasesAny(run.cases_dir, filters)) names.push_back(f.name);
  return names;
}

int runTiers(const TierRuns& runs) {
  const bool with_device = !runs.run.no_device;
  std::string globs;
  for (const std::string& g : runs.filters) globs += (globs.empty() ? "" : " ") + g;
  for (const std::string& tier : runs.tiers) {
    RunOptions o = runs.run;
    o.filters = runs.filters;
    o.filter = globs;  // named by the messages only
    o.model_tier = tier;
    o.no_model = false;
    o.no_device = !with_device || tier != "exact";
    o.out = tierRunDir(runs.out, tier);
    std::printf("== %s: %s, model %s tier%s ==\n", runs.command.c_str(), globs.c_str(),
                tier.c_str(), o.no_device ? "" : " and the device");
    std::fflush(stdout);
    const int rc = runCases(o);
    if (rc == kExitSetup || rc >= 128) return rc;
  }
  return kExitPass;
}

std::optional<Results> readRunBundle(const std::string& dir, const std::string& command) {
  Result<Results> r = readResults(dir);
  if (!r || !r->ok()) {
    const std::string why = r ? r->statusText() : r.error().format();
    std::fprintf(stderr, "rayspec %s: %s: %s; left out\n", command.c_str(), dir.c_str(),
                 visibleLine(why).c_str());
    return std::nullopt;
  }
  return std::move(*r);
}

std::string shortDeviceName(const std::string& device) {
  const size_t cut = device.find(" (");
  return visibleLine(cut == std::string::npos ? device : device.substr(0, cut));
}

Result<OutputFolder> claimStudyFolder(const std::string& out, const std::string& command) {
  std::vector<std::string> writes = {kStudyRunsFolder};
  for (const char* ext : {"txt", "json", "png"}) writes.push_back(command + "." + ext);
  return claimOutputFolder(out, writes, command);
}

std::string studyReport(const std::string& out, const std::string& command, const char* ext) {
  return out + "/" + command + "." + ext;
}

}  // namespace rayspec
