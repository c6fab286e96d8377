#include "fuzz/fuzz_run.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "base/output_folder.h"
#include "base/whole_file.h"
#include "fuzz/finding_report.h"
#include "fuzz/fuzz_tally.h"
#include "fuzz/generate_case.h"
#include "fuzz/saved_cases.h"
#include "mutate/fault_matrix.h"
#include "reduce/reduce_case.h"
#include "report/case_journal.h"
#include "run/interrupt.h"
#include "run/run_loop.h"

namespace rayspec {
namespace {

namespace fs = std::filesystem;

// The case of `seed` written under OUT/cases: generated here, or with
// --saved-cases the text the saved device run ran.
Result<GeneratedCase> writeCase(const FuzzOptions& opt, uint64_t seed) {
  Result<GeneratedCase> made = opt.saved_cases.empty()
                                   ? Result<GeneratedCase>(generateCase(seed, opt.allowed))
                                   : savedCase(opt.saved_cases, opt.run.device_results, seed);
  if (!made) return made;
  const GeneratedCase& g = *made;
  const fs::path file = fs::path(opt.out) / "cases" / (g.name + ".yaml");
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  RAYSPEC_TRY_VOID(writeWholeFile(file.string(), g.yaml));
  return made;
}

// Keeps the first case of a signature: case.yaml and report.md.
void keepFinding(const FuzzOptions& opt, const std::vector<Rule>& catalog, uint64_t seed,
                 const CaseOutcome& o, const FuzzTally::Group& g) {
  const fs::path dir = fs::path(opt.out) / "findings" / g.signature.folder;
  std::error_code ec;
  fs::create_directories(dir, ec);
  const Result<std::string> text = readWholeFile(
      (fs::path(opt.out) / "cases" / (fuzzCaseName(seed) + ".yaml")).string(), uint64_t(1) << 20);
  Result<void> written =
      text ? writeWholeFile((dir / "case.yaml").string(), *text) : Result<void>(text.error());
  if (written)
    written = writeWholeFile((dir / "report.md").string(), findingReport(opt, catalog, seed, o, g));
  if (!written) std::fprintf(stderr, "rayspec fuzz: %s\n", written.error().format().c_str());
}

// Every fault the matrix has not found yet planted in the device results
// of each case of the batch that passed.
void fillFaultMatrix(const FuzzOptions& opt, const RunOptions& run,
                     const std::vector<CaseOutcome>& outcomes, FaultMatrix& matrix) {
  const Result<RunOptions> variant = savedRunVariant(run.out);
  if (!variant) {
    std::fprintf(stderr, "rayspec fuzz: %s\n", variant.error().format().c_str());
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  for (const CaseOutcome& o : outcomes) {
    if (o.verdict.status != Status::Pass || interruptSignal()) continue;
    CaseFile f;
    f.name = o.name;
    f.path = (fs::path(run.cases_dir) / (o.name + ".yaml")).string();
    const Result<SavedCase> saved = loadSavedCase(f, run.cases_dir, run.out, *variant, 0);
    if (saved) matrix.add(o.name, *saved);
  }
  matrix.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Result<void> written =
      writeWholeFile((fs::path(opt.out) / "fault-matrix.txt").string(), matrix.text());
  if (!written) std::fprintf(stderr, "rayspec fuzz: %s\n", written.error().format().c_str());
}

// What every batch reads: the known classes (--known), the rule catalog
// (--rules: each finding's report quotes its rule).
struct FuzzInputs {
  std::vector<KnownClass> known;
  std::vector<Rule> catalog;
};

// One batch: its cases written, run by the run loop, their outcomes
// tallied (and, with a matrix, the faults planted in them). False: nothing
// could run (the run's own error is on stderr), or a signal stopped it.
bool runBatch(const FuzzOptions& opt, const FuzzInputs& in, size_t index, uint64_t first,
              size_t count, FuzzTally& tally, FaultMatrix* matrix) {
  RunOptions run = opt.run;
  run.cases_dir = (fs::path(opt.out) / "cases").string();
  run.out = (fs::path(opt.out) / "runs" / ("batch-" + std::to_string(index))).string();
  run.brief = true;
  run.filters.clear();
  std::map<uint64_t, std::set<std::string>> features;
  for (uint64_t seed = first; seed < first + count; ++seed) {
    const Result<GeneratedCase> g = writeCase(opt, seed);
    ++tally.generated;
    if (!g) {
      std::fprintf(stderr, "rayspec fuzz: %s\n", g.error().format().c_str());
      if (opt.saved_cases.empty()) return false;
      ++tally.unjudged;  // that seed's saved case: the others are judged
      continue;
    }
    run.filters.push_back(g->name);
    features[seed] = g->features;
  }
  if (run.filters.empty()) return true;  // (no filter would run every case)
  const int status = runCases(run, opt.check);
  if (status >= 128 || interruptSignal()) return false;
  const auto journal = readJournal(run.out);
  if (!journal || !*journal) return false;
  for (const CaseOutcome& o : **journal) {
    const uint64_t seed = std::stoull(o.name.substr(o.name.rfind('-') + 1));
    if (const FuzzTally::Group* opened = tally.add(seed, o, knownClassOf(in.known, features[seed])))
      keepFinding(opt, in.catalog, seed, o, *opened);
  }
  if (matrix) fillFaultMatrix(opt, run, **journal, *matrix);
  return status != kExitSetup;
}

void writeFuzzText(const FuzzOptions& opt, const FuzzTally& tally) {
  const Result<void> written =
      writeWholeFile((fs::path(opt.out) / "fuzz.txt").string(), tally.text());
  if (!written) std::fprintf(stderr, "rayspec fuzz: %s\n", written.error().format().c_str());
}

// Each new signature's first case reduced (known classes and defects of
// ours aside: a known bug needs no new report, a defect is triaged by hand).
void reduceFindings(const FuzzOptions& opt, FuzzTally& tally) {
  for (auto& [folder, g] : tally.findings) {
    if (!g.known.empty() || g.rayspec_defect || interruptSignal()) continue;
    const fs::path dir = fs::path(opt.out) / "findings" / folder;
    ReduceOptions r;
    r.case_path =
        (fs::path(opt.out) / "cases" / (fuzzCaseName(g.seeds.front()) + ".yaml")).string();
    r.out = (dir / "reduce").string();
    r.max_attempts = opt.reduce;
    r.run = opt.run;
    r.run.cases_dir = (fs::path(opt.out) / "cases").string();
    const int status = runReduce(r);
    std::error_code ec;
    if (status == kReduceDone)
      fs::copy_file(dir / "reduce" / "reduced.yaml", dir / "reduced.yaml",
                    fs::copy_options::overwrite_existing, ec);
    g.reduced = status == kReduceDone         ? (ec ? "reduced, not copied: " + ec.message()
                                                    : "reduced.yaml (reduce/report.md)")
                : status == kReduceNotFailing ? "the case did not fail again (a flake?)"
                                              : "reduce/ says why it stopped";
  }
}

// --generate-only: the cases of opt.cases seeds written under OUT/cases.
int generateCases(const FuzzOptions& opt) {
  for (uint64_t seed = opt.seed; seed < opt.seed + opt.cases; ++seed) {
    const Result<GeneratedCase> g = writeCase(opt, seed);
    if (!g) {
      std::fprintf(stderr, "rayspec fuzz: %s\n", g.error().format().c_str());
      return kExitSetup;
    }
  }
  std::printf("%zu cases written under %s (seeds %llu to %llu)\n", opt.cases,
              (fs::path(opt.out) / "cases").string().c_str(), (unsigned long long)opt.seed,
              (unsigned long long)(opt.seed + opt.cases - 1));
  return 0;
}

}  // namespace

int runFuzz(const FuzzOptions& opt) {
  Result<std::vector<KnownClass>> known = std::vector<KnownClass>{};
  if (!opt.known.empty()) known = loadKnownClasses(opt.known);
  if (!known) {
    std::fprintf(stderr, "rayspec fuzz: %s\n", known.error().format().c_str());
    return kExitSetup;
  }
  const Result<std::vector<Rule>> catalog = loadRuleCatalog(opt.run.rules_file);
  if (!catalog) {
    std::fprintf(stderr, "rayspec fuzz: %s\n", catalog.error().format().c_str());
    return kExitSetup;
  }
  const FuzzInputs inputs{*known, *catalog};
  const Result<OutputFolder> held = claimOutputFolder(
      opt.out, {"cases", "runs", "findings", "fuzz.txt", "fault-matrix.txt"}, "fuzz");
  if (!held) {
    std::fprintf(stderr, "rayspec fuzz: %s\n", held.error().format().c_str());
    return kExitSetup;
  }
  if (opt.generate_only) return generateCases(opt);
  FuzzTally tally;
  tally.first_seed = opt.seed;
  tally.variant = runVariant(opt.run);
  const auto add_variant = [&](const std::string& v) {
    tally.variant += (tally.variant.empty() ? "" : "; ") + v;
  };
  if (!leftOutText(opt.allowed).empty()) add_variant("cases " + leftOutText(opt.allowed));
  if (!opt.run.plant_fault.empty()) add_variant("planted fault " + opt.run.plant_fault);
  if (!opt.run.device_results.empty())
    add_variant("device results saved in " + opt.run.device_results +
                ": cases a minute counts the judging here, not the device's run");
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::optional<FaultMatrix> matrix;
  if (opt.fault_matrix) matrix.emplace();
  bool ran = true;
  for (size_t b = 0; ran; ++b) {
    const size_t done = tally.generated;
    if (opt.cases ? done >= opt.cases : elapsed() >= 60.0 * opt.minutes) break;
    const size_t count = opt.cases ? std::min(opt.batch, opt.cases - done) : opt.batch;
    ran = runBatch(opt, inputs, b, opt.seed + done, count, tally, matrix ? &*matrix : nullptr);
    tally.seconds = elapsed();
    writeFuzzText(opt, tally);
  }
  if (opt.reduce) {
    reduceFindings(opt, tally);
    writeFuzzText(opt, tally);
  }
  std::printf("%s", tally.text().c_str());
  if (matrix) std::printf("%s", matrix->text().substr(0, matrix->text().find('\n') + 1).c_str());
  if (interruptSignal()) return 128 + interruptSignal();
  if (tally.run == 0 || tally.unjudged) return kExitSetup;
  return tally.findingCases(false) == 0 ? 0 : 1;
}

}  // namespace rayspec
