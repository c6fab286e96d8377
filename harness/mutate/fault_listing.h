// `rayspec faults [--rule R-X]`: every planted fault with the rules it
// breaks (fault/rule_faults.h) and what it breaks (fault/planted_fault.h's
// table, one line per fault); with a rule, its text and section from the
// catalog and its faults.
#pragma once

#include <string>
#include <vector>

#include "run/run_options.h"  // RAYSPEC_SOURCE_DIR

namespace rayspec {

struct FaultsOptions {
  std::string rule;  // "" every fault
  std::string rules_file = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";
};

// "a, b, c".
std::string commaList(const std::vector<std::string>& list);

// 0; 2 when the rule is not in the catalog or the catalog does not read.
int runFaults(const FaultsOptions& opt);

}  // namespace rayspec
