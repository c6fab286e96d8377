// `rayspec list --rules`: which cases check which rule of the catalog. The
// variants of a sweep are shown as the sweep with their count; R-UB cases are
// probes (the device must only survive them) and are listed apart.
#pragma once

#include <string>
#include <vector>

#include "report/rule_catalog.h"

namespace rayspec {

struct ListedCase {
  std::string name;                // the case's name
  std::string sweep;               // the sweep it comes from (<family>/<stem>), or ""
  std::vector<std::string> rules;  // the rules it claims
};

struct RuleListing {
  std::string text;                    // the listing, one rule per block
  std::vector<std::string> uncovered;  // catalog rules (R-UB aside) no case claims
  std::vector<std::string> unknown;    // labels claimed that the catalog lacks
};

RuleListing listRules(const std::vector<Rule>& catalog, const std::vector<ListedCase>& cases);

}  // namespace rayspec
