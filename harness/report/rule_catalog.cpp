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

// One rule: `R-LABEL: title` (a catalog of titles only), or a map of its
// title, text and spec section (references/spec-rules.yaml).
Result<Rule> readRule(const std::string& path, const std::string& label, const YAML::Node& v) {
  if (v.IsScalar()) return Rule{label, v.Scalar(), "", ""};
  if (!v.IsMap())
    return catalogError(path, v.Mark(), label,
                        "expected the rule's title, or a map of its title, text and spec");
  Rule r{label, "", "", ""};
  for (auto it = v.begin(); it != v.end(); ++it) {
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : "";
    std::string* field = key == "title"  ? &r.title
                         : key == "text" ? &r.text
                         : key == "spec" ? &r.spec
                                         : nullptr;
    if (!field)
      return catalogError(path, it->first.Mark(), label + "." + key,
                          "unknown field (a rule has title, text and spec)");
    if (!it->second.IsScalar())
      return catalogError(path, it->second.Mark(), label + "." + key, "expected one string");
    *field = it->second.Scalar();
  }
  if (r.title.empty()) return catalogError(path, v.Mark(), label + ".title", "missing the title");
  return r;
}

}  // namespace

Result<std::vector<Rule>> loadRuleCatalog(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return errorMessage(path +
                        ": no such rule catalog (expected a map of rule labels, R-LABEL, to their "
                        "title, text and spec)");
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
    return Error{SourceLoc{path, 1, 1, ""},
                 "expected a map of rule labels (R-LABEL) to their title, text and spec"};
  std::vector<Rule> rules;
  for (auto it = root.begin(); it != root.end(); ++it) {
    if (!it->first.IsScalar())
      return catalogError(path, it->first.Mark(), "", "expected a rule label (R-NAME) as the key");
    Result<Rule> rule = readRule(path, it->first.Scalar(), it->second);
    if (!rule) return rule.error();
    rules.push_back(std::move(*rule));
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
