#include "report/rule_catalog.h"
#include "base/whole_file.h"
#include "parse/yaml_shape.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

namespace rayspec {

namespace {

constexpr uint64_t kMaxRuleCatalogBytes = 1u << 20;

// An error at a place in the catalog (line and column from yaml-cpp's mark).
Error catalogError(const std::string& path, const YAML::Mark& m, const std::string& field,
                   std::string message) {
  return Error{SourceLoc{path, m.line + 1, m.column + 1, field}, std::move(message)};
}

}  // namespace

Result<std::vector<Rule>> loadRuleCatalog(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return errorMessage(path +
                        ": no such rule catalog (expected a file of `R-LABEL: title` lines)");
  const Result<std::string> text = readWholeFile(path, kMaxRuleCatalogBytes);
  if (!text) return text.error();
  YAML::Node root;
  try {
    root = YAML::Load(*text);
  } catch (const YAML::DeepRecursion& e) {
    return catalogError(path, e.mark, "", yamlTooDeepMessage());
  } catch (const YAML::Exception& e) {
    return catalogError(path, e.mark, "", "malformed YAML: " + e.msg);
  }
  if (const auto problem = yamlShapeProblem(root))
    return catalogError(path, problem->mark, "", problem->message);
  if (!root.IsMap())
    return Error{SourceLoc{path, 1, 1, ""}, "expected a map of `R-LABEL: title` lines"};
  std::vector<Rule> rules;
  for (auto it = root.begin(); it != root.end(); ++it) {
    if (!it->first.IsScalar())
      return catalogError(path, it->first.Mark(), "", "expected a rule label (R-NAME) as the key");
    const std::string label = it->first.Scalar();
    if (!it->second.IsScalar())
      return catalogError(path, it->second.Mark(), label,
                          "expected the rule's title (one line of text)");
    rules.push_back({label, it->second.Scalar()});
  }
  return rules;
}

std::vector<std::string> ruleLabels(const std::vector<Rule>& catalog) {
  std::vector<std::string> labels;
  for (const Rule& r : catalog) labels.push_back(r.label);
  return labels;
}

std::map<std::string, std::vector<std::string>> ruleCoverage(
    const std::vector<Rule>& catalog,
    const std::vector<std::pair<std::string, std::vector<std::string>>>& case_rules) {
  std::map<std::string, std::vector<std::string>> coverage;
  for (const Rule& r : catalog) coverage[r.label];
  for (const auto& [name, rules] : case_rules)
    for (const std::string& r : rules) coverage[r].push_back(name);
  return coverage;
}

}  // namespace rayspec
