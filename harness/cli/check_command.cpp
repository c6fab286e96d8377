// `rayspec check CASE...` and `rayspec run --check-case`: whether every device
// the specification allows passes a case (mutate/case_portability.h), before
// any device runs it.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "base/visible_text.h"
#include "cli/check_command.h"
#include "cli/option_checks.h"
#include "library/case_discovery.h"
#include "model/model_engine.h"
#include "mutate/case_portability.h"
#include "report/rule_catalog.h"

namespace rayspec {
namespace {

struct CheckOptions {
  std::vector<std::string> cases;  // case files or names
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";
  std::string rules_file = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";
  unsigned threads = 0;
};

// The cases an argument names: a case file (a sweep file: each variant), or
// a case name under cases_dir; none when it is neither.
std::vector<CaseFile> casesNamed(const std::string& given, const std::string& cases_dir) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(given, ec)) return caseFilesFor(given, cases_dir);
  if (std::optional<CaseFile> f = findCase(given, "", cases_dir)) return {*f};
  return {};
}

// One case checked and said; whether it is portable.
bool checkOne(const CaseFile& f, const CheckOptions& opt, const std::vector<std::string>& labels) {
  const ParseResult parsed = loadCase(f, opt.cases_dir, &labels);
  if (!parsed.value || !parsed.errors.empty()) {
    std::printf("CaseError     %s\n", visibleLine(f.name).c_str());
    for (const Error& e : parsed.errors) std::printf("  %s\n", visibleLine(e.format()).c_str());
    return false;
  }
  const CasePortability p = checkPortability(*parsed.value, opt.threads);
  if (p.portable()) {
    std::printf(
        "portable      %s (%zu legal devices, %zu of them differ from the model here, "
        "each passes; %.2f s)\n",
        visibleLine(f.name).c_str(), p.devices, p.applied, p.seconds);
    return true;
  }
  if (!p.checked) {
    std::printf("not checked   %s: %s\n", visibleLine(f.name).c_str(),
                visibleLine(p.not_checked).c_str());
  } else if (!p.own_answers.empty()) {
    std::printf("CaseError     %s: the model's own answers do not pass: %s\n",
                visibleLine(f.name).c_str(), visibleLine(p.own_answers).c_str());
  } else {
    std::printf("NOT PORTABLE  %s\n", visibleLine(f.name).c_str());
    for (const NotPortable& problem : p.problems)
      std::printf("  %s\n", visibleLine(notPortableMessage(problem)).c_str());
  }
  return false;
}

int runCheck(const CheckOptions& opt) {
  if (!modelInThisBuild()) {
    std::fprintf(stderr, "rayspec check: this run-only build has no model to check by\n");
    return 2;
  }
  const Result<std::vector<Rule>> catalog = loadRuleCatalog(opt.rules_file);
  if (!catalog) {
    std::fprintf(stderr, "rayspec check: %s\n", catalog.error().format().c_str());
    return 2;
  }
  std::vector<CaseFile> files;
  for (const std::string& given : opt.cases) {
    std::vector<CaseFile> named = casesNamed(given, opt.cases_dir);
    if (named.empty()) {
      std::fprintf(stderr,
                   "rayspec check: no such case file: '%s' (neither a file nor a case name "
                   "under %s)\n",
                   visibleLine(given).c_str(), visibleLine(opt.cases_dir).c_str());
      return 2;
    }
    for (CaseFile& f : named) files.push_back(std::move(f));
  }
  const std::vector<std::string> labels = ruleLabels(*catalog);
  size_t portable = 0;
  for (const CaseFile& f : files) portable += checkOne(f, opt, labels);
  std::printf("%zu of %zu cases portable\n", portable, files.size());
  return portable == files.size() ? 0 : 1;
}

}  // namespace

Subcommand addCheckCommand(CLI::App& app) {
  auto* check = app.add_subcommand(
      "check",
      "Check that a case is portable before any device runs it: the model's exact tier runs it, "
      "then every device the specification allows (each legal answer of an ambiguous ray, a "
      "conservative AABB test, other candidate orders, any-hit run twice, values at the edge of "
      "their tolerance, ...) is judged as a device would be; each one the judge would fail is "
      "named with the declaration of the case to change. Exit 0 every case portable, 1 one is "
      "not (or does not parse), 2 bad input");
  auto opt = std::make_shared<CheckOptions>();
  check->add_option("CASE", opt->cases, "Case files (a sweep: each variant) or case names")
      ->required();
  check->add_option("--cases", opt->cases_dir, "Folder of case files (names cases under it)")
      ->capture_default_str();
  check->add_option("--rules", opt->rules_file, "Rule catalog (references/spec-rules.yaml)")
      ->capture_default_str();
  check->add_option("--threads", opt->threads, "Model threads (0: all cores)")
      ->check(wholeCount())
      ->capture_default_str();
  return {check, [opt] {
            return runCheck(*opt);
          }};
}

void addCheckCaseOptions(CLI::App* run, RunOptions& run_opt) {
  CLI::Option* on = run->add_flag_callback(
      "--check-case", [&run_opt] { run_opt.check_case = true; },
      "Check every case against the devices the specification allows before it runs (as "
      "`rayspec check`): one that such a device would fail is a CaseError naming the "
      "declaration to change, and does not run. Default: the cases outside the library folder "
      "(" RAYSPEC_SOURCE_DIR "/cases) are checked");
  run->add_flag_callback(
         "--no-check-case", [&run_opt] { run_opt.check_case = false; },
         "Check no case against the devices the specification allows (not even those outside "
         "the library folder)")
      ->excludes(on);
}

CaseCheck portabilityCheckFor(const RunOptions& opt) {
  if (opt.no_model || !modelInThisBuild()) return {};
  return [threads = opt.threads](const Case& c) {
    return notPortableText(checkPortability(c, threads));
  };
}

}  // namespace rayspec
