#include "report/rule_catalog.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

namespace rayspec {

std::vector<Rule> loadRuleCatalog(const std::string& path, std::string* error) {
  std::vector<Rule> rules;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    *error = path + ": no such rule catalog (expected a file of `R-LABEL: title` lines)";
    return rules;
  }
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  auto at = [&](const YAML::Mark& m, const std::string& field) {
    return path + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1) + ": " +
           (field.empty() ? "" : field + ": ");
  };
  YAML::Node root;
  try {
    root = YAML::Load(text.str());
  } catch (const YAML::Exception& e) {
    *error = at(e.mark, "") + "malformed YAML: " + e.msg;
    return {};
  }
  if (!root.IsMap()) {
    *error = path + ":1:1: expected a map of `R-LABEL: title` lines";
    return {};
  }
  for (auto it = root.begin(); it != root.end(); ++it) {
    if (!it->first.IsScalar()) {
      *error = at(it->first.Mark(), "") + "expected a rule label (R-NAME) as the key";
      return {};
    }
    const std::string label = it->first.Scalar();
    if (!it->second.IsScalar()) {
      *error = at(it->second.Mark(), label) + "expected the rule's title (one line of text)";
      return {};
    }
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
