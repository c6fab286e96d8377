#include "report/rule_catalog.h"

#include <yaml-cpp/yaml.h>

namespace rayspec {

std::vector<Rule> loadRuleCatalog(const std::string& path, std::string* error) {
  std::vector<Rule> rules;
  try {
    const YAML::Node root = YAML::LoadFile(path);
    for (const auto& kv : root) rules.push_back({kv.first.as<std::string>(), kv.second.as<std::string>()});
  } catch (const YAML::Exception& e) {
    *error = path + ": " + e.what();
  }
  return rules;
}

std::map<std::string, std::vector<std::string>> ruleCoverage(
    const std::vector<Rule>& catalog, const std::vector<std::pair<std::string, std::vector<std::string>>>& case_rules) {
  std::map<std::string, std::vector<std::string>> coverage;
  for (const Rule& r : catalog) coverage[r.label];
  for (const auto& [name, rules] : case_rules)
    for (const std::string& r : rules) coverage[r].push_back(name);
  return coverage;
}

}  // namespace rayspec
