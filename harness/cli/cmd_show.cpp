#include <cstdio>
#include <filesystem>

#include "base/whole_file.h"
#include "cli/commands.h"
#include "cli/describe_case.h"
#include "cli/model_expectations.h"
#include "glsl/generate_glsl.h"
#include "library/case_discovery.h"
#include "model/model_engine.h"
#include "mutate/case_portability.h"
#include "parse/parse_aim.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "program/builtins.h"
#include "program/ops.h"
#include "report/rule_catalog.h"

namespace rayspec {
namespace {

// The stages column of a built-in or an operator: "all stages" or their names.
std::string stagesText(StageMask stages) {
  return "[" + (stages == kAllStages ? std::string("all stages") : stageList(stages)) + "]";
}

void printVocabulary() {
  std::printf("Built-ins (name, type, meaning, [the stages that may read it]):\n");
  for (const BuiltinInfo& b : builtins())
    std::printf("  %-24s %-6s %s %s\n", b.name, valueTypeName(b.type), b.meaning,
                stagesText(b.stages).c_str());
  std::printf("\nOperators (name, arguments, meaning, [the stages that may use it]):\n");
  for (const OpInfo& o : ops())
    std::printf("  %-20s %d..%d  %s %s\n", o.name, o.min_args, o.max_args, o.meaning,
                stagesText(o.stages).c_str());
}

const char* const kRulesFile = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";

void printShader(const GeneratedShader& s) {
  std::printf("\n--- %s (%s) ---\n%s", s.name.c_str(), stageName(s.stage), s.glsl.c_str());
}

// The case's text: a sweep variant's substituted text, else its file's.
std::string caseText(const CaseFile& f) {
  if (f.generated) return f.text;
  const Result<std::string> text = readWholeFile(f.path, kMaxCaseFileBytes);
  return text ? *text : std::string();
}

// What the model expects of each ray, and whether every device the
// specification allows passes the case (as `rayspec check`).
void printModelAndPortability(const Case& c) {
  if (!modelInThisBuild()) {
    std::printf("\nModel: none in this run-only build (no expectations, no portability check)\n");
    return;
  }
  Results model;
  const CasePortability p = checkPortability(c, 0, &model);
  std::printf("\n%s", describeModelExpectations(c, model).c_str());
  if (p.portable())
    std::printf(
        "Portable: every device the specification allows passes it (%zu legal devices, "
        "%zu of them differ from the model here)\n",
        p.devices, p.applied);
  else if (!p.checked)
    std::printf("Portability not checked: %s\n", p.not_checked.c_str());
  else if (!p.own_answers.empty())
    std::printf("NOT PORTABLE: the model's own answers do not pass: %s\n", p.own_answers.c_str());
  else
    std::printf("NOT PORTABLE:\n  %s\n", notPortableText(p).c_str());
}

}  // namespace

std::optional<CaseFile> caseToShow(const std::string& given, const std::string& cases_dir,
                                   const char* verb) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(given, ec)) {
    std::vector<CaseFile> files = caseFilesFor(given, cases_dir);
    if (files.size() > 1) {
      std::printf("%s is a sweep of %zu cases; %s the first (name one to take it):\n",
                  given.c_str(), files.size(), verb);
      for (const CaseFile& f : files) std::printf("  %s\n", f.name.c_str());
      std::printf("\n");
    }
    return files.front();
  }
  return findCase(given, "", cases_dir);
}

int runShow(const ShowOptions& opt) {
  if (opt.vocabulary) {
    printVocabulary();
    if (opt.case_file.empty()) return 0;
  }
  if (opt.case_file.empty()) {
    std::fprintf(stderr, "rayspec show: give a case file or name\n");
    return 2;
  }
  const std::optional<CaseFile> file = caseToShow(opt.case_file, opt.cases_dir, "showing");
  if (!file) {
    std::fprintf(
        stderr, "rayspec show: no such case file: '%s' (neither a file nor a case name under %s)\n",
        opt.case_file.c_str(), opt.cases_dir.c_str());
    return 2;
  }
  // Rule labels outside the catalog are errors, as in `rayspec run`.
  const Result<std::vector<Rule>> loaded = loadRuleCatalog(kRulesFile);
  if (!loaded)
    std::fprintf(stderr, "rayspec show: %s (rule labels not checked)\n",
                 loaded.error().format().c_str());
  const std::vector<std::string> catalog =
      loaded ? ruleLabels(*loaded) : std::vector<std::string>{};
  ParseResult parsed = loadCase(*file, opt.cases_dir, loaded ? &catalog : nullptr);
  for (const Error& e : parsed.errors) std::fprintf(stderr, "%s\n", e.format().c_str());
  if (!parsed.value) return 1;
  const Case& c = *parsed.value;
  const Plan plan = derivePlan(c);
  std::printf("%s", describeCase(c).c_str());
  std::printf("%s", describeAimTargets(aimTargetsOf(c, caseText(*file))).c_str());
  std::printf("\nPlan (what both backends build):\n");
  for (const std::string& line : plan.describe()) std::printf("%s\n", line.c_str());
  if (!opt.no_model) printModelAndPortability(c);
  if (!opt.no_glsl) {
    const GeneratedPipeline g = generateGlsl(c, plan);
    printShader(g.raygen);
    for (const auto& other : g.other_raygens) printShader(other);
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
