#include "report/merge_runs.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include "base/plain_tree.h"
#include "report/baseline_gate.h"
#include "report/rule_catalog.h"

namespace rayspec {
namespace fs = std::filesystem;
namespace {

// The case folder `name` of `from` into `to`: hard links, or copies.
std::string copyCaseFolder(const std::string& from, const std::string& to,
                           const std::string& name) {
  const fs::path src = fs::path(from) / name, dst = fs::path(to) / name;
  std::error_code ec;
  if (const std::string odd = plainPathProblem(from, name); !odd.empty())
    return "refusing to merge " + src.string() + ": " + odd +
           " (a shard holds only regular files and folders)";
  if (!fs::exists(src, ec)) return {};  // a CaseError or skipped case may have none
  fs::remove_all(dst, ec);
  fs::create_directories(dst.parent_path(), ec);
  fs::copy(src, dst, fs::copy_options::recursive | fs::copy_options::create_hard_links, ec);
  if (ec) {
    fs::remove_all(dst, ec);
    ec.clear();
    fs::copy(src, dst, fs::copy_options::recursive, ec);
  }
  return ec ? "cannot copy " + src.string() + " to " + dst.string() + ": " + ec.message()
            : std::string();
}

}  // namespace

std::string variantText(const std::string& variant) {
  return variant.empty() ? "as written" : "by " + variant;
}

MergeResult mergeRuns(const std::vector<std::string>& dirs, const std::string& out,
                      const Baseline& baseline, const std::vector<Rule>& catalog) {
  MergeResult m;
  std::vector<SavedRun> runs;
  std::map<std::string, std::string> seen;  // case -> folder
  for (const std::string& dir : dirs) {
    std::error_code ec;
    if (fs::equivalent(dir, out, ec)) {
      m.error = "the output folder " + out + " is one of the folders to merge";
      return m;
    }
    Result<SavedRun> read = readSavedRun(dir);
    if (!read) {
      m.error = read.error().format();
      return m;
    }
    SavedRun& run = *read;
    if (!runs.empty() && run.info.variant != runs[0].info.variant) {
      m.error = dir + " ran its cases " + variantText(run.info.variant) + ", " + dirs[0] + " " +
                variantText(runs[0].info.variant) + ": only runs of one variant merge";
      return m;
    }
    if (!runs.empty() && (run.info.device != runs[0].info.device ||
                          run.info.model_tier != runs[0].info.model_tier)) {
      m.error = dir + " was run on '" + run.info.device + "' (model " + run.info.model_tier +
                "), " + dirs[0] + " on '" + runs[0].info.device + "' (model " +
                runs[0].info.model_tier + "): only runs of one device and tier merge";
      return m;
    }
    for (const CaseOutcome& o : run.outcomes) {
      if (auto [it, fresh] = seen.emplace(o.name, dir); !fresh) {
        m.error = "case " + o.name + " is in both " + it->second + " and " + dir;
        return m;
      }
    }
    runs.push_back(std::move(run));
  }
  if (runs.empty()) {
    m.error = "no folder to merge";
    return m;
  }
  RunInfo& info = m.run.info;
  info = runs[0].info;
  info.planned_cases = 0;
  info.teardown_errors.clear();
  info.catalog = catalog;
  if (!baseline.empty()) info.baseline = baseline.file;
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
      if (const std::string err = copyCaseFolder(dirs[i], out, o.name); !err.empty()) {
        m.error = err;
        return m;
      }
      // A flake was found by its run's re-run, which a merge cannot repeat.
      if (!baseline.empty() && o.baseline != BaselineMatch::Flake) applyBaseline(baseline, o);
      case_rules.push_back({o.name, o.rules});
      m.run.outcomes.push_back(std::move(o));
    }
  }
  std::sort(m.run.outcomes.begin(), m.run.outcomes.end(),
            [](const CaseOutcome& a, const CaseOutcome& b) { return a.name < b.name; });
  info.coverage = ruleCoverage(catalog, case_rules);
  m.error = writeReports(m.run.outcomes, info, out);
  return m;
}

}  // namespace rayspec
