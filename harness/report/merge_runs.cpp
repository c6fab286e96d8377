#include "report/merge_runs.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include "base/output_folder.h"
#include "base/plain_tree.h"
#include "report/baseline_gate.h"
#include "report/rule_catalog.h"
#include "report/run_folder_writes.h"

namespace rayspec {
namespace fs = std::filesystem;
namespace {

// The error (ErrorKind::Input) of a case folder `name` of shard `from` that
// holds an entry that is no regular file or folder (a link would lead the
// judge and the copy elsewhere).
Result<void> plainCaseFolder(const std::string& from, const std::string& name) {
  if (const std::string odd = plainPathProblem(from, name); !odd.empty())
    return errorMessage("refusing to merge " + (fs::path(from) / name).string() + ": " + odd +
                        " (a shard holds only regular files and folders)");
  return {};
}

// The case folder `name` of `from` into `to`: hard links, or copies. The
// error: ErrorKind::Input, an entry that is no regular file or folder;
// ErrorKind::Harness, the copy failed.
Result<void> copyCaseFolder(const std::string& from, const std::string& to,
                            const std::string& name) {
  const fs::path src = fs::path(from) / name, dst = fs::path(to) / name;
  std::error_code ec;
  RAYSPEC_TRY_VOID(plainCaseFolder(from, name));
  if (!fs::exists(src, ec)) return {};  // a CaseError or skipped case may have none
  fs::remove_all(dst, ec);
  fs::create_directories(dst.parent_path(), ec);
  fs::copy(src, dst, fs::copy_options::recursive | fs::copy_options::create_hard_links, ec);
  if (ec) {
    fs::remove_all(dst, ec);
    ec.clear();
    fs::copy(src, dst, fs::copy_options::recursive, ec);
  }
  if (ec)
    return errorOf(ErrorKind::Harness,
                   "cannot copy " + src.string() + " to " + dst.string() + ": " + ec.message());
  return {};
}

// The case as `judge` finds it in `shard`, judged by the baseline anew; an
// unexpected failure by its re-run there (a flake only where the re-run
// gave another result).
Result<void> judgeAnew(const ShardCaseJudge& judge, const Baseline& baseline,
                       const std::string& shard, const RunInfo& info, CaseOutcome& o) {
  RAYSPEC_TRY(std::optional<CaseOutcome> judged, judge(shard, info, o, false));
  if (judged) o = std::move(*judged);
  if (!applyBaseline(baseline, o)) return {};
  RAYSPEC_TRY(const std::optional<CaseOutcome> rerun, judge(shard, info, o, true));
  if (rerun)
    applyRerun(o, *rerun);
  else
    o.baseline_note += "; " + shard + " holds no re-run of it to tell a flake by";
  return {};
}

}  // namespace

std::string variantText(const std::string& variant) {
  return variant.empty() ? "as written" : "by " + variant;
}

Result<SavedRun> mergeRuns(const std::vector<std::string>& dirs, const std::string& out,
                           const Baseline& baseline, const std::vector<Rule>& catalog,
                           const ShardCaseJudge& judge) {
  std::vector<SavedRun> runs;
  std::map<std::string, std::string> seen;  // case -> folder
  for (const std::string& dir : dirs) {
    std::error_code ec;
    if (fs::equivalent(dir, out, ec))
      return errorMessage("the output folder " + out + " is one of the folders to merge");
    RAYSPEC_TRY(SavedRun run, readSavedRun(dir));
    if (!runs.empty() && run.info.variant != runs[0].info.variant)
      return errorMessage(dir + " ran its cases " + variantText(run.info.variant) + ", " + dirs[0] +
                          " " + variantText(runs[0].info.variant) +
                          ": only runs of one variant merge");
    if (!runs.empty() &&
        (run.info.device != runs[0].info.device || run.info.model_tier != runs[0].info.model_tier))
      return errorMessage(dir + " was run on '" + run.info.device + "' (model " +
                          run.info.model_tier + "), " + dirs[0] + " on '" + runs[0].info.device +
                          "' (model " + runs[0].info.model_tier +
                          "): only runs of one device and tier merge");
    for (const CaseOutcome& o : run.outcomes)
      if (auto [it, fresh] = seen.emplace(o.name, dir); !fresh)
        return errorMessage("case " + o.name + " is in both " + it->second + " and " + dir);
    for (CaseOutcome& o : run.outcomes) {
      RAYSPEC_TRY_VOID(plainCaseFolder(dir, o.name));
      RAYSPEC_TRY_VOID(judgeAnew(judge, baseline, dir, run.info, o));
    }
    runs.push_back(std::move(run));
  }
  if (runs.empty()) return errorMessage("no folder to merge");
  std::vector<std::string> names;
  for (const auto& [name, dir] : seen) names.push_back(name);
  RAYSPEC_TRY(const OutputFolder held, claimOutputFolder(out, runFolderWrites(names), "merge"));
  SavedRun merged;
  RunInfo& info = merged.info;
  info = runs[0].info;
  info.planned_cases = 0;
  info.teardown_errors.clear();
  info.catalog = catalog;
  info.baseline = baseline.file;  // the shards' own are gone: every case was judged anew
  std::vector<std::pair<std::string, std::vector<std::string>>> case_rules;
  for (size_t i = 0; i < runs.size(); ++i) {
    const RunInfo& r = runs[i].info;
    info.started = std::min(info.started, r.started);
    info.validation = info.validation && r.validation;
    info.planned_cases += std::max(r.planned_cases, runs[i].outcomes.size());
    info.interrupted = info.interrupted || r.interrupted;
    info.teardown_errors.insert(info.teardown_errors.end(), r.teardown_errors.begin(),
                                r.teardown_errors.end());
    for (CaseOutcome& o : runs[i].outcomes) {
      RAYSPEC_TRY_VOID(copyCaseFolder(dirs[i], out, o.name));
      case_rules.push_back({o.name, o.rules});
      merged.outcomes.push_back(std::move(o));
    }
  }
  std::sort(merged.outcomes.begin(), merged.outcomes.end(),
            [](const CaseOutcome& a, const CaseOutcome& b) { return a.name < b.name; });
  info.coverage = ruleCoverage(catalog, case_rules);
  RAYSPEC_TRY_VOID(writeReports(merged.outcomes, info, out));
  return merged;
}

}  // namespace rayspec
