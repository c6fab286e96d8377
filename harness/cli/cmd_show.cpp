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
  std::string path = opt.case_file;
  if (!std::filesystem::exists(path)) path = opt.cases_dir + "/" + opt.case_file + ".yaml";
  const CaseFile file = caseFileFor(path, opt.cases_dir);
  ParseResult parsed = parseCaseFile(file.path, opt.cases_dir);
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
