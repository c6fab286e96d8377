// The model in each tier, and the device beside the exact tier, run over one
// set of cases into run folders through `rayspec run`'s own machinery
// (run/run_loop.h: child processes, results bundles): OUT/<tier>/<case>/model
// and OUT/exact/<case>/device. Shared by `rayspec stability` and `rayspec
// accuracy`, which then read the bundles back (readRunBundle).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/output_folder.h"
#include "results/results.h"
#include "run/run_options.h"

namespace rayspec {

struct TierRuns {
  RunOptions
      run;  // device, cases folder, limits, baseline (run.filter and run.out are set per run)
  std::vector<std::string> filters;  // globs: the set is every case matching one of them
  std::vector<std::string> tiers = {"fast", "robust", "exact"};  // the device runs beside "exact"
  std::string out;                                               // the run folders: out/<tier>
  std::string command;  // "stability": names the progress lines and notes
};

// The --out of a study (`command`: "stability", "accuracy"), claimed for
// it (base/output_folder.h): its tier runs in runs/ and its report
// <command>.txt, .json and .png.
inline constexpr const char* kStudyRunsFolder = "runs";
Result<OutputFolder> claimStudyFolder(const std::string& out, const std::string& command);
// The report file of a study with this extension ("txt", "json", "png").
std::string studyReport(const std::string& out, const std::string& command, const char* ext);

// The run folder of one tier.
std::string tierRunDir(const std::string& out, const std::string& tier);

// The names of the cases matching any of the globs, sorted, each once.
std::vector<std::string> tierRunCases(const RunOptions& run,
                                      const std::vector<std::string>& filters);

// Runs every tier (the device too unless run.no_device), one `rayspec run`
// of every case matching a glob (RunOptions::filters) into the tier's
// folder. Returns kExitPass when every run got as far as its cases (failing
// cases included), else the first run's kExitSetup or 128 + signal.
int runTiers(const TierRuns& runs);

// A side's results bundle, or nothing (with a note on stderr starting with
// `command`) when it is missing or did not end normally.
std::optional<Results> readRunBundle(const std::string& dir, const std::string& command);

// The device's name up to its first " (": "llvmpipe (LLVM 15, ...)" -> "llvmpipe";
// a label of the tables (and their console copy), shown by the visible-text
// rule (base/visible_text.h visibleLine): a saved bundle's name is input.
std::string shortDeviceName(const std::string& device);

}  // namespace rayspec
