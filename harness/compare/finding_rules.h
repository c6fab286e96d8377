// Which rules a wrong value can be evidence against, so that a finding names
// them, and a claim is proven only by a finding that names it
// (fault/prove_claim.cpp): a wrong hit_kind speaks of R-HITKIND-TRI and of
// R-FACE-DET, never of R-RECURSION.
#pragma once

#include <string>
#include <vector>

#include "case/case.h"

namespace rayspec {

// The rules a per-ray field's value can break.
std::vector<std::string> rulesEvidencedByField(const std::string& field);
// The rules a counter can break: by the stages that count it.
std::vector<std::string> rulesEvidencedByCounter(const Case& c, const std::string& counter);

// A finding's rule: the evidenced rules the case claims, joined by '/'
// ("R-FACE-DET/R-HITKIND-TRI"); `own` when the case claims none of them.
std::string findingRule(const std::vector<std::string>& evidenced,
                        const std::vector<std::string>& case_rules, const std::string& own);

}  // namespace rayspec
