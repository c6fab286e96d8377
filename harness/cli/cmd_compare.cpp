// rayspec compare A B: judges saved results without running anything.
//   two bundles (folders with results.json): A against B (e.g. device / model)
//   two run folders: for every case of A, A/<case>/device against
//   B/<case>/device (one driver against another, today against last week);
//   the rays' legal answers come from B's (else A's) model bundle.
// Each case is the one of its name under --cases, made as the runs' variant
// (summary.json) made it; every bundle must be that case's as it is here
// (its case_hash), as `rayspec run --device-results` checks a saved one.
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "base/output_folder.h"
#include "base/visible_text.h"
#include "bundle/image_files.h"
#include "bundle/results_io.h"
#include "cli/commands.h"
#include "cli/option_checks.h"
#include "report/outcome_json.h"
#include "report/rule_catalog.h"
#include "report/run_folder_writes.h"
#include "report/run_summary.h"
#include "report/write_reports.h"
#include "results/file_name.h"
#include "run/case_as_run.h"
#include "run/case_steps.h"
#include "run/device_results.h"
#include "run/judge_case.h"
#include "run/run_loop.h"
#include "run/saved_case.h"

namespace rayspec {
namespace fs = std::filesystem;
namespace {

bool isBundle(const fs::path& p) {
  return fs::exists(p / "results.json");
}

struct Pair {
  std::string name;
  fs::path a, b, ambiguity;  // ambiguity: a model bundle whose ambiguous rays to use ("" = b's own)
};

std::vector<Pair> pairsOf(const fs::path& a, const fs::path& b) {
  if (isBundle(a)) return {{"", a, b, {}}};
  std::vector<Pair> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(a, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().filename() != "results.json" || it->path().parent_path().filename() != "device")
      continue;
    const fs::path case_dir = it->path().parent_path().parent_path();
    // A case's re-run (<case>/rerun/device) is that case's, not one of its own.
    if (case_dir.filename() == "rerun" && isBundle(case_dir.parent_path() / "device")) continue;
    const std::string name = case_dir.lexically_relative(a).generic_string();
    fs::path ambiguity = b / name / "model";
    if (!isBundle(ambiguity)) ambiguity = case_dir / "model";
    out.push_back({name, case_dir / "device", b / name / "device",
                   isBundle(ambiguity) ? ambiguity : fs::path()});
  }
  std::sort(out.begin(), out.end(), [](const Pair& x, const Pair& y) { return x.name < y.name; });
  return out;
}

CaseOutcome failedOutcome(const std::string& name, Status s, const std::string& message) {
  CaseOutcome o;
  o.name = name;
  o.verdict.add({s, s == Status::NotSupported ? "" : "compare", message, {}, 0});
  o.deriveFromVerdict();
  return o;
}

// Where the case the bundles are judged by comes from: looked up by name
// under --cases (never a file a results.json names), made as the runs'
// variant made it.
struct CaseSource {
  CaseIndex cases;
  RunOptions variant;
};

CaseOutcome compareOne(const Pair& p, const CompareOptions& opt, const CaseSource& source,
                       std::vector<std::string>* rules) {
  Result<Results> read_a = readResults(p.a.string());
  // An unreadable bundle or case file is not the driver's fault: a CaseError.
  if (!read_a)
    return caseErrorOutcome(p.name.empty() ? p.a.string() : p.name, {}, "bundle",
                            read_a.error().format());
  const std::string name = p.name.empty() ? read_a->case_name : p.name;
  if (!isBundle(p.b))
    return failedOutcome(name, Status::NotSupported,
                         "no reference: " + p.b.string() + " has no results");
  const Result<Case> found = caseHere(name, source.variant, source.cases);
  if (!found) return caseErrorOutcome(name, {}, "case-file", found.error().format());
  const Case& c = *found;
  *rules = c.rules;
  const Plan plan = derivePlan(c);
  // Each bundle is this case's as it is here (run/device_results.h).
  if (const Result<void> mine = checkCaseBundle(*read_a, p.a.string(), c, plan); !mine)
    return caseErrorOutcome(name, c.rules, "bundle", mine.error().format());
  const Results& a = *read_a;
  Result<Results> read_b = readCaseBundle(p.b.string(), c, plan);
  if (!read_b) return caseErrorOutcome(name, c.rules, "bundle", read_b.error().format());
  Results& b = *read_b;
  if (!p.ambiguity.empty()) {
    const Result<Results> m = readCaseBundle(p.ambiguity.string(), c, plan);
    if (!m) return caseErrorOutcome(name, c.rules, "bundle", m.error().format());
    b.ambiguous = m->ambiguous;
  }
  const std::string dir = opt.out + "/" + name;
  removeCaseOutputs(dir);
  // Pictures for people, best effort: the comparison reads the texels.
  for (const Image& im : a.images) (void)writeImageFiles(im, dir + "/device");
  for (const Image& im : b.images) (void)writeImageFiles(im, dir + "/model");
  CaseOutcome o = judgeCase(c, plan, a, b, dir);
  o.device_name = a.device;
  o.seconds = a.seconds;
  return o;
}

// The variant the compared runs ran their cases by (summary.json of a run
// folder; "" for bundles); the error: two runs of different variants, or a
// summary.json that does not read.
Result<std::string> comparedVariant(const CompareOptions& opt) {
  std::optional<std::string> variant;
  std::string first;
  for (const std::string& side : {opt.a, opt.b}) {
    std::error_code ec;
    if (isBundle(side) || !fs::exists(fs::path(side) / "summary.json", ec)) continue;
    RAYSPEC_TRY(const SavedRun run, readSavedRun(side));
    if (variant && *variant != run.info.variant)
      return errorMessage(side + " ran its cases " + variantText(run.info.variant) + ", " + first +
                          " " + variantText(*variant) + ": only runs of one variant compare");
    variant = run.info.variant;
    first = side;
  }
  return variant.value_or("");
}

// The cases under --cases and the runs' variant; the error says why not.
Result<CaseSource> caseSource(const CompareOptions& opt) {
  CaseSource source{indexCases(opt.cases_dir), {}};
  RAYSPEC_TRY(const std::string variant, comparedVariant(opt));
  if (const Result<void> read = variantOptions(variant, source.variant); !read)
    return errorMessage("variant '" + variant + "': " + read.error().message);
  return source;
}

}  // namespace

int runCompare(const CompareOptions& opt) {
  for (const std::string& side : {opt.a, opt.b})
    if (!fs::is_directory(side)) {
      std::fprintf(stderr,
                   "rayspec compare: %s is not a folder (a results bundle or a run folder)\n",
                   side.c_str());
      return kExitSetup;
    }
  if (const std::string overlap = outputOverlapsInputs(opt.out, {opt.a, opt.b}); !overlap.empty()) {
    std::fprintf(stderr, "rayspec compare: %s: its reports would replace what is compared\n",
                 overlap.c_str());
    return kExitSetup;
  }
  const Result<CaseSource> source = caseSource(opt);
  if (!source) {
    std::fprintf(stderr, "rayspec compare: %s\n", source.error().format().c_str());
    return kExitSetup;
  }
  const std::vector<Pair> pairs = pairsOf(opt.a, opt.b);
  if (pairs.empty()) {
    std::fprintf(stderr,
                 "rayspec compare: %s holds no results (no results.json, no <case>/device/)\n",
                 opt.a.c_str());
    return kExitSetup;
  }
  std::vector<std::string> names;
  for (const Pair& p : pairs) names.push_back(p.name);
  const Result<OutputFolder> held = claimOutputFolder(opt.out, runFolderWrites(names), "compare");
  if (!held) {
    std::fprintf(stderr, "rayspec compare: %s\n", visibleLine(held.error().format()).c_str());
    return kExitSetup;
  }
  RunInfo info;
  char text[64];
  const std::time_t t = std::time(nullptr);
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&t));
  info.started = text;
  info.model_tier = "reference " + opt.b;
  if (Result<std::vector<Rule>> catalog = loadRuleCatalog(opt.rules_file))
    info.catalog = std::move(*catalog);  // without one, the report lists no rule coverage
  std::printf("Comparing %s against %s\n", opt.a.c_str(), opt.b.c_str());
  RunSummary summary(pairs.size(),
                     opt.brief ? RunSummary::Progress::Brief : RunSummary::Progress::Every);
  std::vector<std::pair<std::string, std::vector<std::string>>> case_rules;
  for (const Pair& p : pairs) {
    summary.starting(p.name);
    std::vector<std::string> rules;
    CaseOutcome o = guardCase(p.name, {}, [&] { return compareOne(p, opt, *source, &rules); });
    if (!rules.empty()) case_rules.push_back({o.name, rules});
    if (info.device.empty()) info.device = o.device_name;
    summary.add(o);
  }
  info.coverage = ruleCoverage(info.catalog, case_rules);
  summary.print(opt.brief);
  if (const Result<void> written = writeReports(summary.outcomes(), info, opt.out); !written) {
    std::fprintf(stderr, "rayspec compare: the reports are not complete: %s\n",
                 visibleLine(written.error().format()).c_str());
    return kExitReports;
  }
  std::printf("Reports: %s/report.html, results.csv, junit.xml, summary.json\n", opt.out.c_str());
  if (summary.failed()) return kExitFailing;
  if (summary.allNotSupported()) {
    std::fprintf(stderr,
                 "rayspec compare: nothing was compared: no case of %s has a counterpart in %s\n",
                 opt.a.c_str(), opt.b.c_str());
    return kExitNothingCompared;
  }
  return kExitPass;
}

}  // namespace rayspec
