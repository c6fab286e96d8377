// The stability report: runs, counts, files.
#include "stability/run_stability.h"

#include <cstdio>
#include <filesystem>

#include "base/whole_file.h"
#include "library/case_discovery.h"
#include "run/run_loop.h"
#include "stability/stability_table.h"
#include "tiers/tier_runs.h"

namespace rayspec {
namespace {

struct StabilityCase {
  std::string name, family, magnitude_text;
  double magnitude = 0;
};

// The filter's cases that belong to a stability family: a sweep variant with
// a numeric `magnitude` parameter.
std::vector<StabilityCase> stabilityCases(const RunOptions& run) {
  std::vector<StabilityCase> out;
  for (const CaseFile& f : findCases(run.cases_dir, run.filter)) {
    for (const auto& [key, value] : f.params) {
      if (key != "magnitude") continue;
      StabilityCase c;
      c.name = f.name;
      const size_t a = f.name.find('/'), b = f.name.find('/', a + 1);
      if (a == std::string::npos || b == std::string::npos) continue;
      c.family = f.name.substr(a + 1, b - a - 1);
      c.magnitude_text = value;
      try {
        c.magnitude = std::stod(value);
      } catch (const std::exception&) {
        std::fprintf(stderr, "rayspec stability: %s: magnitude '%s' is not a number; left out\n",
                     f.path.c_str(), value.c_str());
        continue;
      }
      out.push_back(c);
    }
  }
  return out;
}

// A side's results bundle, counted; false (with a note) when it is missing
// or did not end normally.
bool countBundle(const std::string& dir, LeakCounts* counts, std::string* device) {
  const std::optional<Results> r = readRunBundle(dir, "stability");
  if (!r) return false;
  *counts = countLeaks(*r);
  if (device) *device = stabilityDeviceSource(r->device, r->driver);
  return true;
}

}  // namespace

constexpr const char* kCommand = "stability";

int runStability(const StabilityOptions& opt) {
  const std::vector<StabilityCase> cases = stabilityCases(opt.run);
  if (cases.empty()) {
    std::fprintf(
        stderr,
        "rayspec stability: no case matching '%s' in %s has a `magnitude` sweep parameter\n",
        opt.run.filter.c_str(), opt.run.cases_dir.c_str());
    return kExitSetup;
  }
  const Result<OutputFolder> held = claimStudyFolder(opt.out, kCommand);
  if (!held) {
    std::fprintf(stderr, "rayspec stability: %s\n", held.error().format().c_str());
    return kExitSetup;
  }
  const bool with_device = !opt.run.no_device;
  const std::string runs = opt.out + "/" + kStudyRunsFolder;
  if (const int rc = runTiers({opt.run, {opt.run.filter}, opt.tiers, runs, kCommand});
      rc != kExitPass)
    return rc;
  std::vector<StabilityEntry> entries;
  bool exact_clean = true;
  for (const StabilityCase& c : cases)
    for (const std::string& tier : opt.tiers) {
      const std::string dir = tierRunDir(runs, tier) + "/" + c.name;
      StabilityEntry e{c.family, c.magnitude, c.magnitude_text, "model " + tier, {}};
      if (countBundle(dir + "/model", &e.counts, nullptr)) {
        addCounts(entries, e);
        if (tier == "exact" && (e.counts.leaks || e.counts.doubles)) {
          exact_clean = false;
          std::fprintf(
              stderr,
              "rayspec stability: %s: the exact tier leaks %llu and double-hits %llu rays\n",
              c.name.c_str(), (unsigned long long)e.counts.leaks,
              (unsigned long long)e.counts.doubles);
        }
      }
      std::string device;
      if (with_device && tier == "exact" && countBundle(dir + "/device", &e.counts, &device)) {
        e.source = device;
        addCounts(entries, e);
      }
    }
  for (const std::string& saved : opt.saved_devices)
    for (const StabilityCase& c : cases) {
      StabilityEntry e{c.family, c.magnitude, c.magnitude_text, "", {}};
      std::string device;
      if (!countBundle(saved + "/" + c.name + "/device", &e.counts, &device)) continue;
      e.source = device;
      addCounts(entries, e);
    }
  std::filesystem::create_directories(opt.out);
  const std::string table = formatStabilityTable(entries);
  Result<void> written = writeWholeFile(studyReport(opt.out, kCommand, "txt"), table);
  if (written)
    written = writeWholeFile(studyReport(opt.out, kCommand, "json"),
                             stabilityJson(entries).dump(2) + "\n");
  std::string error = written ? std::string() : written.error().format();
  if (error.empty()) {
    const PlotLayout layout{static_cast<int>(stabilitySources(entries).size()), 330, 290,
                            "Leaks and double hits per 1000 rays (rows: families; columns: "
                            "model tiers and devices)"};
    if (Result<void> r =
            writePlots(studyReport(opt.out, kCommand, "png"), stabilityPanels(entries), layout);
        !r)
      error = r.error().format();
  }
  std::printf("\n%s\nReport: %s/stability.txt, stability.json, stability.png\n", table.c_str(),
              opt.out.c_str());
  if (!error.empty()) {
    std::fprintf(stderr, "rayspec stability: %s\n", error.c_str());
    return kExitFailing;
  }
  return exact_clean ? kExitPass : kExitFailing;
}

}  // namespace rayspec
