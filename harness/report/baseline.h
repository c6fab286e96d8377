// Known failures of one driver, for regression checks: a CSV file in
// deqp-runner's baseline form, one `case,Status` line each (statuses by their
// rayspec names), '#' comments saying why. A case whose status equals its
// baseline entry is an expected result: reported as such, and it does not fail
// the run. A case that got better (its baseline says Fail, it passes) is an
// unexpected pass: reported so the baseline can shrink; it does not fail.
// Anything else that is not Pass fails as usual.
#pragma once

#include <map>
#include <string>

#include "compare/verdict.h"
#include "report/case_outcome.h"

namespace rayspec {

struct Baseline {
  std::string file;
  std::map<std::string, Status> expected;  // case name -> status
};

// Reads a baseline; error names the file and line of a malformed entry.
Baseline loadBaseline(const std::string& path, std::string* error);

// Sets outcome.baseline from the baseline entry of its case, if any.
void applyBaseline(const Baseline& baseline, CaseOutcome& outcome);

}  // namespace rayspec
