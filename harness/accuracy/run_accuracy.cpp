// The accuracy report: runs, per-ray comparison, files.
#include "accuracy/run_accuracy.h"

#include <cstdio>
#include <filesystem>
#include <optional>

#include "accuracy/accuracy_table.h"
#include "base/whole_file.h"
#include "library/case_discovery.h"
#include "run/run_loop.h"
#include "tiers/tier_runs.h"

namespace rayspec {
namespace {

constexpr const char* kCommand = "accuracy";

// The case a bundle ran, parsed (for its triangles), if it still parses.
std::optional<Case> caseOf(const std::string& name, const Results& r,
                           const std::string& cases_dir) {
  const std::optional<CaseFile> f = findCase(name, r.case_file, cases_dir);
  if (!f) return std::nullopt;
  ParseResult p = loadCase(*f, cases_dir);
  return std::move(p.value);
}

AccuracyRow rowFor(CaseSet set, const std::string& source, SourceKind kind, const Results& exact,
                   const Results& other, const Case* c) {
  AccuracyRow row;
  row.set = set;
  row.source = source;
  row.kind = kind;
  row.cases = 1;
  row.launch_rays = uint64_t(other.width) * other.height;
  row.trace_seconds =
      other.cost[kind == SourceKind::Device ? CostStep::Trace : CostStep::ModelTrace];
  row.d = countDisagreements(exact, other, c);
  return row;
}

// One saved device bundle of the case, if the folder has one of the same case.
std::optional<Results> savedBundle(const std::string& dir, const std::string& name,
                                   const Results& exact) {
  const std::string bundle = dir + "/" + name + "/device";
  std::error_code ec;
  if (!std::filesystem::exists(bundle + "/results.json", ec)) return std::nullopt;
  std::optional<Results> r = readRunBundle(bundle, kCommand);
  if (r && r->case_hash && exact.case_hash && r->case_hash != exact.case_hash) {
    std::fprintf(stderr, "rayspec accuracy: %s: ran another version of the case; left out\n",
                 bundle.c_str());
    return std::nullopt;
  }
  return r;
}

// Runs one set and adds its rows; kExitPass, or the runs' kExitSetup / 128 + signal.
int measureSet(const AccuracyOptions& opt, CaseSet set, const std::vector<std::string>& globs,
               std::vector<AccuracyRow>& rows) {
  const std::vector<std::string> names = tierRunCases(opt.run, globs);
  if (names.empty()) {
    std::fprintf(stderr, "rayspec accuracy: no %s case matches the globs given\n",
                 caseSetName(set));
    return kExitPass;
  }
  const std::string runs = opt.out + "/" + kStudyRunsFolder + "/" + caseSetName(set);
  if (const int rc = runTiers(
          {opt.run, globs, opt.tiers, runs, std::string(kCommand) + " " + caseSetName(set)});
      rc != kExitPass)
    return rc;
  const std::string exact_dir = tierRunDir(runs, "exact");
  for (const std::string& name : names) {
    const std::optional<Results> exact = readRunBundle(exact_dir + "/" + name + "/model", kCommand);
    if (!exact) continue;
    const std::optional<Case> c = caseOf(name, *exact, opt.run.cases_dir);
    const Case* cp = c ? &*c : nullptr;
    for (const std::string& tier : opt.tiers) {
      const std::optional<Results> model =
          tier == "exact" ? exact
                          : readRunBundle(tierRunDir(runs, tier) + "/" + name + "/model", kCommand);
      if (model)
        addToRow(rows, rowFor(set, "model " + tier, SourceKind::ModelTier, *exact, *model, cp));
    }
    if (!opt.run.no_device)
      if (const std::optional<Results> dev =
              readRunBundle(exact_dir + "/" + name + "/device", kCommand))
        addToRow(rows,
                 rowFor(set, shortDeviceName(dev->device), SourceKind::Device, *exact, *dev, cp));
    for (const std::string& saved : opt.saved_devices)
      if (const std::optional<Results> dev = savedBundle(saved, name, *exact))
        addToRow(rows,
                 rowFor(set, shortDeviceName(dev->device), SourceKind::Device, *exact, *dev, cp));
  }
  return kExitPass;
}

}  // namespace

int runAccuracy(const AccuracyOptions& opt) {
  if (tierRunCases(opt.run, opt.ordinary).empty() && tierRunCases(opt.run, opt.hard).empty()) {
    std::fprintf(stderr, "rayspec accuracy: no case in %s matches the ordinary or the hard globs\n",
                 opt.run.cases_dir.c_str());
    return kExitSetup;
  }
  bool has_exact = false;
  for (const std::string& t : opt.tiers) has_exact = has_exact || t == "exact";
  if (!has_exact) {
    std::fprintf(stderr,
                 "rayspec accuracy: the exact tier is the reference: it must be among the tiers\n");
    return kExitSetup;
  }
  const Result<OutputFolder> held = claimStudyFolder(opt.out, kCommand);
  if (!held) {
    std::fprintf(stderr, "rayspec accuracy: %s\n", held.error().format().c_str());
    return kExitSetup;
  }
  std::vector<AccuracyRow> rows;
  for (CaseSet set : {CaseSet::Ordinary, CaseSet::Hard})
    if (const int rc =
            measureSet(opt, set, set == CaseSet::Ordinary ? opt.ordinary : opt.hard, rows);
        rc != kExitPass)
      return rc;
  std::filesystem::create_directories(opt.out);
  const std::string table = formatAccuracyTable(rows);
  Result<void> written = writeWholeFile(studyReport(opt.out, kCommand, "txt"), table);
  if (written)
    written =
        writeWholeFile(studyReport(opt.out, kCommand, "json"), accuracyJson(rows).dump(2) + "\n");
  std::string error = written ? std::string() : written.error().format();
  if (error.empty()) {
    const std::vector<PlotPanel> panels = accuracyPanels(rows);
    if (panels.empty()) {
      error = "nothing to plot: no bundle was read";
    } else if (Result<void> r = writePlots(studyReport(opt.out, kCommand, "png"), panels,
                                           {2, 560, 420, "What accuracy costs in time"});
               !r) {
      error = r.error().format();
    }
  }
  std::printf("\n%s\nReport: %s/accuracy.txt, accuracy.json, accuracy.png\n", table.c_str(),
              opt.out.c_str());
  if (!error.empty()) {
    std::fprintf(stderr, "rayspec accuracy: %s\n", error.c_str());
    return kExitFailing;
  }
  return kExitPass;
}

}  // namespace rayspec
