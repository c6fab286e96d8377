#include "mutate/mutate_run.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "base/output_folder.h"
#include "base/whole_file.h"
#include "library/case_discovery.h"
#include "model/model_engine.h"
#include "mutate/kill_matrix.h"
#include "report/outcome_json.h"
#include "run/case_as_run.h"
#include "run/device_results.h"

namespace rayspec {
namespace fs = std::filesystem;
namespace {

CaseMutation notJudged(const std::string& name, const std::string& why) {
  CaseMutation m;
  m.name = name;
  m.family = caseFamily(name);
  m.not_judged = why;
  return m;
}

}  // namespace

Result<RunOptions> savedRunVariant(const std::string& run_dir) {
  RunOptions variant;
  std::error_code ec;
  if (!fs::exists(fs::path(run_dir) / "summary.json", ec)) return variant;
  RAYSPEC_TRY(const SavedRun run, readSavedRun(run_dir));
  if (const Result<void> read = variantOptions(run.info.variant, variant); !read)
    return errorMessage(run_dir + "/summary.json: variant: " + read.error().message);
  return variant;
}

namespace {

CaseMutation mutateOne(const CaseFile& f, const MutateOptions& opt, const RunOptions& variant) {
  Result<SavedCase> saved = loadSavedCase(f, opt.cases_dir, opt.run_dir, variant, opt.threads);
  if (!saved) return notJudged(f.name, saved.error().message);
  return mutateCase(saved->c, saved->plan, saved->device, saved->model, opt.threads);
}

// Why a run gave mutate no case: none of the cases it ran (its summary.json's,
// or its <case> folders') is a case file under --cases, the folder the cases
// are read from (a run of case files kept outside the library); or --filter
// left none.
std::string noCaseFoundText(const MutateOptions& opt) {
  std::vector<std::string> ran;
  if (const Result<SavedRun> run = readSavedRun(opt.run_dir))
    for (const CaseOutcome& o : run->outcomes) ran.push_back(o.name);
  std::error_code ec;
  if (ran.empty())
    for (const fs::directory_entry& e : fs::directory_iterator(opt.run_dir, ec))
      if (fs::exists(e.path() / "device" / "results.json", ec))
        ran.push_back(e.path().filename().string());
  std::set<std::string> library;
  for (const CaseFile& f : findCases(opt.cases_dir, "*")) library.insert(f.name);
  for (const std::string& name : ran)
    if (library.count(name))
      return "no case of it under " + opt.cases_dir + " matches --filter '" + opt.filter +
             "' and has a device bundle (<case>/device/results.json)";
  std::string names;
  for (size_t i = 0; i < ran.size() && i < 3; ++i) names += (i ? ", " : "") + ran[i];
  if (ran.size() > 3) names += ", ...";
  return "none of the " + std::to_string(ran.size()) + " case(s) " + opt.run_dir + " ran" +
         (names.empty() ? "" : " (" + names + ")") + " is a case file under " + opt.cases_dir +
         ", the folder mutate reads the cases from; for cases kept elsewhere, pass --cases "
         "FOLDER, the folder that holds the run's case files";
}

// The reports of a kill matrix in --out.
constexpr const char* kMutateText = "mutate.txt";
constexpr const char* kMutateJson = "mutate.json";

}  // namespace

Result<SavedCase> loadSavedCase(const CaseFile& f, const std::string& cases_dir,
                                const std::string& run_dir, const RunOptions& variant,
                                unsigned threads) {
  const ParseResult parsed = loadCase(f, cases_dir);
  if (!parsed.value) {
    std::string why = "case file error";
    for (const Error& e : parsed.errors) why += "; " + e.format();
    return errorMessage(why);
  }
  const CaseAsRun as_run = caseAsRun(*parsed.value, variant);
  if (as_run.not_run) return errorMessage(as_run.not_run->headline);
  SavedCase s{*as_run.runs, derivePlan(*as_run.runs), {}, {}};
  Result<Results> device = SavedDevice(run_dir).run(s.c, s.plan);
  if (!device) return errorMessage(device.error().format());
  if (!device->ok()) return errorMessage("device: " + device->statusText());
  s.device = std::move(*device);
  ModelOptions mo;
  mo.threads = threads;
  s.model = runOnModel(s.c, s.plan, mo);
  if (!s.model.ok()) return errorMessage("model: " + s.model.statusText());
  return s;
}

int runMutate(const MutateOptions& opt) {
  if (!modelInThisBuild()) {
    std::fprintf(stderr, "rayspec mutate: this run-only build has no model to judge by\n");
    return 2;
  }
  std::error_code ec;
  if (!fs::is_directory(opt.run_dir, ec)) {
    std::fprintf(stderr,
                 "rayspec mutate: %s is not a folder (a run folder with <case>/device bundles)\n",
                 opt.run_dir.c_str());
    return 2;
  }
  const Result<OutputFolder> held =
      claimOutputFolder(opt.out, {kMutateText, kMutateJson}, "mutate");
  if (!held) {
    std::fprintf(stderr, "rayspec mutate: %s\n", held.error().format().c_str());
    return 2;
  }
  const Result<RunOptions> variant = savedRunVariant(opt.run_dir);
  if (!variant) {
    std::fprintf(stderr, "rayspec mutate: %s\n", variant.error().format().c_str());
    return 2;
  }
  std::vector<CaseMutation> cases;
  for (const CaseFile& f : findCases(opt.cases_dir, opt.filter)) {
    if (!fs::exists(fs::path(savedBundleDir(opt.run_dir, f.name)) / "results.json")) continue;
    cases.push_back(mutateOne(f, opt, *variant));
  }
  const KillMatrix m = buildKillMatrix(cases);
  const std::string text = killMatrixText(m);
  std::printf("%s", text.c_str());
  const std::string device = savedDevices(opt.run_dir, findCases(opt.cases_dir, opt.filter));
  Result<void> written = writeWholeFile(opt.out + "/" + kMutateText, text);
  if (written)
    written = writeWholeFile(opt.out + "/" + kMutateJson, killMatrixJson(m, opt.run_dir, device));
  if (!written) {
    std::fprintf(stderr, "rayspec mutate: %s\n", written.error().format().c_str());
    return 2;
  }
  if (cases.empty()) {
    std::fprintf(stderr, "rayspec mutate: no case of %s could be judged: %s\n", opt.run_dir.c_str(),
                 noCaseFoundText(opt).c_str());
    return 1;
  }
  if (!m.judged) {
    std::fprintf(stderr, "rayspec mutate: no case of %s could be judged (why, for each: above)\n",
                 opt.run_dir.c_str());
    return 1;
  }
  return m.unexplained() == 0 && m.nullKilled() == m.nullApplied() && m.false_alarms.empty() ? 0
                                                                                             : 1;
}

}  // namespace rayspec
