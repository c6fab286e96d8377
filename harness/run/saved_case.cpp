#include "run/saved_case.h"

#include <filesystem>
#include <memory>

#include "base/visible_text.h"
#include "plan/plan.h"
#include "run/case_as_run.h"
#include "run/case_steps.h"
#include "run/device_results.h"

namespace rayspec {
namespace fs = std::filesystem;
namespace {

Error cannotJudge(const std::string& message) {
  return errorOf(ErrorKind::Harness, message);
}

// Why an outcome made without judging is what it is: its first finding.
std::string firstFinding(const CaseOutcome& o) {
  return o.verdict.findings.empty() ? o.headline : o.verdict.findings[0].message;
}

// Whether a run's device (summary.json's "device": "NAME (DRIVER)", or with
// --device-results the saved bundles' devices, "A, B") names the device a
// bundle of it ran on.
bool runNamesDevice(const std::string& run, const std::string& device) {
  for (size_t at = run.find(device); at != std::string::npos; at = run.find(device, at + 1)) {
    const size_t end = at + device.size();
    const bool starts = at == 0 || (at >= 2 && run.compare(at - 2, 2, ", ") == 0);
    const bool ends =
        end == run.size() || run.compare(end, 2, ", ") == 0 || run.compare(end, 2, " (") == 0;
    if (starts && ends) return true;
  }
  return false;
}

// The device the case's bundle ran on is the one the shard's summary.json
// names, for the case and for the run; the error names the field.
Result<void> sameDevice(const std::string& summary, const RunInfo& info, const CaseOutcome& claimed,
                        const CaseOutcome& judged, const std::string& folder) {
  const std::string bundle = folder + "/device/results.json";
  const std::string ran = " ran on '" + visibleText(judged.device_name, 120) + "'";
  if (claimed.device_name != judged.device_name)
    return errorMessage(summary + ": case " + claimed.name + ": device_name '" +
                        visibleText(claimed.device_name, 120) + "', but its bundle " + bundle +
                        ran + ": the case's verdict is not that device's");
  if (!judged.device_name.empty() && !runNamesDevice(info.device, judged.device_name))
    return errorMessage(summary + ": device '" + visibleText(info.device, 120) +
                        "', but the bundle " + bundle + " of case " + claimed.name + ran +
                        ": the run's verdicts are not that device's");
  return {};
}

// The verdict of the bundles, with the times the shard measured; where the
// summary said another status, a finding quotes it.
CaseOutcome asJudged(const std::string& summary, const CaseOutcome& claimed, CaseOutcome judged) {
  judged.seconds = claimed.seconds;
  judged.cost = claimed.cost;
  if (judged.status == claimed.status) return judged;
  judged.verdict.add({Status::QualityWarning,
                      "merge",
                      summary + " says " + statusName(claimed.status) + " (" +
                          visibleLine(claimed.headline.substr(0, 200)) +
                          "); its bundles, judged "
                          "anew, say " +
                          statusName(judged.status),
                      {},
                      0});
  judged.deriveFromVerdict();
  return judged;
}

// A case whose folder holds no bundle did not run there (skipped, a case-file
// error, not run by the variant): the summary's word is kept where it says
// the case did not pass; a pass without bundles is refused.
Result<std::optional<CaseOutcome>> withoutBundles(const std::string& summary,
                                                  const std::string& folder,
                                                  const CaseOutcome& claimed) {
  if (claimed.status == Status::Pass || claimed.status == Status::QualityWarning)
    return errorMessage(summary + ": case " + claimed.name + ": status " +
                        statusName(claimed.status) + ", but " + folder +
                        " holds no bundle (device/results.json, model/results.json): nothing "
                        "shows it ran");
  return std::optional<CaseOutcome>(claimed);
}

// judgeSavedCase, with an exception of the standard library made its error.
Result<std::optional<CaseOutcome>> judgedOrError(const std::string& folder, const std::string& name,
                                                 const RunOptions& variant,
                                                 const CaseIndex& cases) {
  try {
    return judgeSavedCase(folder, name, variant, cases);
  } catch (const std::exception& e) {
    return cannotJudge(e.what());
  }
}

// The re-run of a case in its folder (folder/rerun): judged where it holds
// the sides the case's own bundles hold and judges cleanly; nullopt
// otherwise (no re-run to tell a flake by).
std::optional<CaseOutcome> rerunOf(const std::string& folder, const std::string& name,
                                   const RunOptions& variant, const CaseIndex& cases) {
  const std::string again = folder + "/rerun";
  if (!(savedSides(again) == savedSides(folder))) return std::nullopt;
  Result<std::optional<CaseOutcome>> judged = judgedOrError(again, name, variant, cases);
  if (!judged) return std::nullopt;
  return std::move(*judged);
}

Result<std::optional<CaseOutcome>> judgeShardCase(const CaseIndex& cases, const std::string& shard,
                                                  const RunInfo& info, const CaseOutcome& claimed,
                                                  bool rerun) {
  const std::string summary = (fs::path(shard) / "summary.json").string();
  RunOptions variant;
  if (const Result<void> read = variantOptions(info.variant, variant); !read)
    return errorMessage(summary + ": variant: " + read.error().message);
  const std::string folder = (fs::path(shard) / claimed.name).string();
  if (rerun) return rerunOf(folder, claimed.name, variant, cases);
  Result<std::optional<CaseOutcome>> judged = judgedOrError(folder, claimed.name, variant, cases);
  if (!judged)
    return std::optional<CaseOutcome>(
        caseErrorOutcome(claimed.name, claimed.rules, "harness",
                         "cannot judge " + folder + " anew: " + judged.error().format()));
  if (!*judged) return withoutBundles(summary, folder, claimed);
  RAYSPEC_TRY_VOID(sameDevice(summary, info, claimed, **judged, folder));
  return std::optional<CaseOutcome>(asJudged(summary, claimed, std::move(**judged)));
}

}  // namespace

Result<Case> caseHere(const std::string& name, const RunOptions& variant, const CaseIndex& cases) {
  const auto found = cases.by_name.find(name);
  if (found == cases.by_name.end())
    return cannotJudge("no case " + name + " under " + cases.dir + " to judge its bundles by");
  const CaseFile& file = found->second;
  const ParseResult parsed = loadCase(file, cases.dir);
  if (const std::optional<CaseOutcome> error = caseFileError(file, parsed))
    return cannotJudge("its case file does not parse here: " + firstFinding(*error));
  CaseAsRun as_run = caseAsRun(*parsed.value, variant);
  if (as_run.not_run) return cannotJudge("it has bundles, but " + firstFinding(*as_run.not_run));
  return std::move(*as_run.runs);
}

SavedSides savedSides(const std::string& folder) {
  std::error_code ec;
  return {fs::exists(fs::path(folder) / "device" / "results.json", ec),
          fs::exists(fs::path(folder) / "model" / "results.json", ec)};
}

CaseIndex indexCases(const std::string& cases_dir) {
  CaseIndex index{cases_dir, {}};
  for (CaseFile& f : findCases(cases_dir, "*")) {
    std::string name = f.name;
    index.by_name.emplace(std::move(name), std::move(f));
  }
  return index;
}

Result<std::optional<CaseOutcome>> judgeSavedCase(const std::string& folder,
                                                  const std::string& name,
                                                  const RunOptions& variant,
                                                  const CaseIndex& cases) {
  const SavedSides sides = savedSides(folder);
  if (!sides.device && !sides.model) return std::optional<CaseOutcome>();
  RAYSPEC_TRY(const Case c, caseHere(name, variant, cases));
  const Plan plan = derivePlan(c);
  std::optional<Results> device, model;
  if (sides.device) {
    RAYSPEC_TRY(device, readCaseBundle(folder + "/device", c, plan));
  }
  if (sides.model) {
    RAYSPEC_TRY(model, readCaseBundle(folder + "/model", c, plan));
  }
  return std::optional<CaseOutcome>(
      judgeSides(c, plan, device ? &*device : nullptr, model ? &*model : nullptr, ""));
}

ShardCaseJudge shardCaseJudge(const std::string& cases_dir) {
  auto cases = std::make_shared<const CaseIndex>(indexCases(cases_dir));
  return [cases](const std::string& shard, const RunInfo& info, const CaseOutcome& claimed,
                 bool rerun) {
    return judgeShardCase(*cases, shard, info, claimed, rerun);
  };
}

}  // namespace rayspec
