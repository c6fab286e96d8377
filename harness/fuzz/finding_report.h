// OUT/findings/<signature>/report.md of `rayspec fuzz` (fuzz/fuzz_run.h):
// the finding's first case (seed, triage, known class), the specification's
// text of its rule as the rule catalog holds it (references/spec-rules.yaml,
// read by report/rule_catalog.h), the verdict's findings and how to run the
// case again.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/fuzz_run.h"
#include "fuzz/fuzz_tally.h"
#include "report/case_outcome.h"
#include "report/rule_catalog.h"

namespace rayspec {

// The rule section of a report: each label of `labels` ("R-A" or "R-A/R-B")
// with its title, text and specification section; a label the catalog lacks
// is said to be so.
std::string ruleSection(const std::vector<Rule>& catalog, const std::string& labels);

// report.md of the signature `g` whose first case is `seed`'s outcome `o`.
std::string findingReport(const FuzzOptions& opt, const std::vector<Rule>& catalog, uint64_t seed,
                          const CaseOutcome& o, const FuzzTally::Group& g);

}  // namespace rayspec
