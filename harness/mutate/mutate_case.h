// One case's device results judged under every generic mutant.
#pragma once

#include <string>
#include <vector>

#include "compare/verdict.h"
#include "mutate/generic_mutant.h"
#include "mutate/legal_devices.h"

namespace rayspec {

struct MutantOutcome {
  std::string kind, name;
  Mutation mutation;
  bool killed = false;  // the mutated results fail (isFailing)
  Status status = Status::Pass;
  std::string headline;      // the verdict's
  std::string legal_reason;  // a survivor: why it may legally survive ("" = none: a hole)
};

struct CaseMutation {
  std::string name, family;  // family: the case's first folder
  bool judged = false;       // false: the unmutated results do not pass, or were not there
  std::string not_judged;    // why
  std::vector<MutantOutcome> mutants;
  std::vector<LegalDevice> legal_devices;  // each must not fail (legal_devices.h)
  // Wall seconds spent on the legal devices and on the generic mutants.
  double legal_seconds = 0, mutant_seconds = 0;
};

// The unmutated device results must pass (Pass or QualityWarning) for the
// mutants to say anything; then each mutant is applied to a copy and judged.
// The legal devices are judged whatever the saved results say (they are
// made from the model); `threads` for their model runs.
CaseMutation mutateCase(const Case& c, const Plan& plan, const Results& device,
                        const Results& model, unsigned threads = 0);

}  // namespace rayspec
