#include "fuzz/finding_report.h"

#include <filesystem>
#include <sstream>

#include "fuzz/generate_case.h"

namespace rayspec {

std::string ruleSection(const std::vector<Rule>& catalog, const std::string& labels) {
  std::string r;
  std::stringstream parts(labels);
  for (std::string label; std::getline(parts, label, '/');) {
    const Rule* rule = nullptr;
    for (const Rule& c : catalog)
      if (c.label == label) rule = &c;
    if (!rule) {
      r += "## " + label + "\n\nNot in the rule catalog.\n\n";
      continue;
    }
    r += "## " + label + ": " + rule->title + "\n\n";
    if (!rule->text.empty()) r += rule->text + "\n\n";
    if (!rule->spec.empty()) r += "Specification: " + rule->spec + "\n\n";
  }
  return r;
}

std::string findingReport(const FuzzOptions& opt, const std::vector<Rule>& catalog, uint64_t seed,
                          const CaseOutcome& o, const FuzzTally::Group& g) {
  namespace fs = std::filesystem;
  const FuzzSignature& s = g.signature;
  const bool defect = g.rayspec_defect;
  std::string r = "# " + s.status + " " + s.rule + ": " + s.kind + "\n\n";
  r += "Seed " + std::to_string(seed) + " (case " + fuzzCaseName(seed) + ", case.yaml here).";
  r += defect ? " Triage: a rayspec defect (a CaseError not of the model's checks, or the "
                "model's own crash or hang).\n\n"
              : "\n\n";
  if (!g.known.empty())
    r += "Known class (the case holds its feature; check that the bug is that one): " + g.known +
         "\n\n";
  // A rule of the catalog (not a kind of our own: case-file, generated-shader).
  if (s.rule.rfind("R-", 0) == 0) r += ruleSection(catalog, s.rule);
  r += "Headline: " + o.headline + "\n\nFindings:\n\n";
  for (const Finding& f : o.verdict.findings) {
    r += "- " + std::string(statusName(f.status)) + " " + f.rule + ": " + f.message;
    if (f.ray_count) r += " (" + std::to_string(f.ray_count) + " rays)";
    r += "\n";
  }
  r += "\nRun it again: `rayspec run --cases " + (fs::path(opt.out) / "cases").string() +
       " --filter " + fuzzCaseName(seed) + " --out DIR`" +
       (opt.run.plant_fault.empty() ? "" : " --plant-fault " + opt.run.plant_fault) +
       (opt.run.through ? " --through " + std::string(featurePathName(*opt.run.through)) : "") +
       "\n";
  return r;
}

}  // namespace rayspec
