// The rules of the coverage contract (references/spec-rules.yaml: each rule's
// label, title, text and spec section), and which cases check which rule.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "base/result.h"

namespace rayspec {

struct Rule {
  std::string label, title;
  std::string text;  // the requirement in our words ("" in a catalog of titles only)
  std::string spec;  // the specification's section it comes from
};

// Reads the catalog, or the error that says why not: the file is missing, or
// malformed at FILE:LINE:COL (with the rule's label where known).
Result<std::vector<Rule>> loadRuleCatalog(const std::string& path);

// The labels of the catalog, for the case parser (parse/parse_case.h), which
// reports a label outside it at its line:col.
std::vector<std::string> ruleLabels(const std::vector<Rule>& catalog);

// rule label -> case names, for every rule of the catalog (empty = uncovered),
// plus labels the cases use that the catalog lacks.
std::map<std::string, std::vector<std::string>> ruleCoverage(
    const std::vector<Rule>& catalog,
    const std::vector<std::pair<std::string, std::vector<std::string>>>& case_rules);

}  // namespace rayspec
