// Which rules a wrong value can be evidence against, so that a finding names
// one rule (its headline's) and keeps the claims it evidences, and a claim is
// proven only by a finding that names it (fault/prove_claim.cpp): a wrong
// hit_kind speaks of R-HITKIND-TRI and of R-FACE-DET, never of R-RECURSION.
#pragma once

#include <string>
#include <vector>

#include "case/case.h"
#include "compare/verdict.h"

namespace rayspec {

// The rules a per-ray field's value can break.
std::vector<std::string> rulesEvidencedByField(const std::string& field);
// The rules a counter can break: by the stages that count it.
std::vector<std::string> rulesEvidencedByCounter(const Case& c, const std::string& counter);

// The rule a finding names, and the rules the case claims that it is
// evidence against (a claim's proof reads both: fault/rule_faults.h namesRule).
struct FindingRule {
  std::string rule;
  std::vector<std::string> evidence;  // the evidenced rules the case claims, in its order
};

// A finding's rule, of the evidenced rules the case claims: `own` (the
// field's rule, results/record_field_table.h) where claimed; else the one
// claimed, or the one claimed that is not a rule of how the pipeline is built
// and run (those every value evidences); else `own`. Where `own` is no rule
// (a counter's "counter"), the claims joined by '/' ("R-FACE-DET/R-INST-XFORM").
FindingRule findingRule(const std::vector<std::string>& evidenced,
                        const std::vector<std::string>& case_rules, const std::string& own);
// A finding of `status` that says `message`, naming the rules of `r`.
Finding findingOf(Status status, const FindingRule& r, std::string message);

}  // namespace rayspec
