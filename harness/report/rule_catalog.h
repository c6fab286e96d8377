// The rule labels of the coverage contract (references/spec-rules.yaml, a copy
// of the labels of ../shared/spec-rules.md with short titles), and which cases
// check which rule.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rayspec {

struct Rule {
  std::string label, title;
};

// Reads the catalog; error set when the file is missing or malformed.
std::vector<Rule> loadRuleCatalog(const std::string& path, std::string* error);

// rule label -> case names, for every rule of the catalog (empty = uncovered),
// plus labels the cases use that the catalog lacks.
std::map<std::string, std::vector<std::string>> ruleCoverage(
    const std::vector<Rule>& catalog, const std::vector<std::pair<std::string, std::vector<std::string>>>& case_rules);

}  // namespace rayspec
