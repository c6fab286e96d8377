#include <cstdio>
#include <filesystem>

#include "case/parse_case.h"
#include "run/case_discovery.h"
#include "cli/commands.h"
#include "cli/describe_case.h"
#include "glsl/generate_glsl.h"
#include "plan/plan.h"
#include "program/builtins.h"
#include "program/ops.h"
#include "report/rule_catalog.h"

namespace rayspec {
namespace {

void printVocabulary() {
  std::printf("Built-ins (name, type, meaning):\n");
  for (const BuiltinInfo& b : builtins())
    std::printf("  %-24s %-6s %s\n", b.name, valueTypeName(b.type), b.meaning);
  std::printf("\nOperators (name, arguments, meaning):\n");
  for (const OpInfo& o : ops())
    std::printf("  %-20s %d..%d  %s\n", o.name, o.min_args, o.max_args, o.meaning);
}

const char* const kRulesFile = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";

// The case file a `show` argument names: a path to a file, or a case name
// under cases_dir (anyhit/ignore-odd-primitives); empty when neither exists.
std::string caseFilePath(const std::string& given, const std::string& cases_dir) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(given, ec)) return given;
  const std::string named = cases_dir + "/" + given + ".yaml";
  if (std::filesystem::is_regular_file(named, ec)) return named;
  return {};
}

void printShader(const GeneratedShader& s) {
  std::printf("\n--- %s (%s) ---\n%s", s.name.c_str(), stageName(s.stage), s.glsl.c_str());
}

}  // namespace

int runShow(const ShowOptions& opt) {
  if (opt.vocabulary) {
    printVocabulary();
    if (opt.case_file.empty()) return 0;
  }
  if (opt.case_file.empty()) {
    std::fprintf(stderr, "rayspec show: give a case file or name\n");
    return 2;
  }
  const std::string path = caseFilePath(opt.case_file, opt.cases_dir);
  if (path.empty()) {
    std::fprintf(stderr, "rayspec show: no such case file: '%s' (neither a file nor a case name under %s)\n",
                 opt.case_file.c_str(), opt.cases_dir.c_str());
    return 2;
  }
  const CaseFile file = caseFileFor(path, opt.cases_dir);
  // Rule labels outside the catalog are errors, as in `rayspec run`.
  std::string catalog_error;
  const std::vector<std::string> catalog = ruleLabels(loadRuleCatalog(kRulesFile, &catalog_error));
  if (!catalog_error.empty()) std::fprintf(stderr, "rayspec show: %s (rule labels not checked)\n", catalog_error.c_str());
  ParseResult parsed = parseCaseFile(file.path, opt.cases_dir, catalog_error.empty() ? &catalog : nullptr);
  for (const CaseError& e : parsed.errors) std::fprintf(stderr, "%s\n", e.format().c_str());
  if (!parsed.value) return 1;
  const Case& c = *parsed.value;
  const Plan plan = derivePlan(c);
  std::printf("%s", describeCase(c).c_str());
  std::printf("\nPlan (what both backends build):\n");
  for (const std::string& line : plan.describe()) std::printf("%s\n", line.c_str());
  if (!opt.no_glsl) {
    const GeneratedPipeline g = generateGlsl(c, plan);
    printShader(g.raygen);
    for (const auto& m : g.miss) printShader(m);
    for (const auto& h : g.hit_groups) {
      if (h.intersection) printShader(*h.intersection);
      if (h.any_hit) printShader(*h.any_hit);
      if (h.closest_hit) printShader(*h.closest_hit);
    }
    for (const auto& cl : g.callables) printShader(cl);
  }
  return 0;
}

}  // namespace rayspec
