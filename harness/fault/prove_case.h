// Proving a whole case: every rule it claims (Case::rules) by the faults of
// rule_faults.h, the model's exact tier standing for the device. The one
// proof behind `rayspec prove` and the library's ctest (fault/Cases/<family>).
#pragma once

#include <vector>

#include "case/case.h"
#include "compare/verdict.h"
#include "fault/rule_faults.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

struct CaseProof {
  Plan plan;
  Results model;                   // the model's exact tier
  Results perfect;                 // the device the faults are planted in (perfectDevice)
  Verdict clean;                   // the perfect device judged: it must pass
  std::vector<ClaimProof> claims;  // one per claimed rule, in the case's order
  Verdict reversed;  // a device finding candidates far to near: it must pass (R-ORDER-UNSPEC)
  // The model ran, the perfect and the reversed device pass, and every claim
  // is proven (or, R-UB, never checked).
  bool ok() const;
};

// A claim's result that leaves the case proven: Proven, or NotChecked (R-UB).
bool claimHolds(const ClaimProof& p);

// The break that made the case give what the rule expects (Fail, or
// QualityWarning for a "should"); null when none did.
const FaultOutcome* provingFault(const ClaimProof& p);

// `threads` for the model (0: all cores). The claims are not judged when the
// model does not run or the perfect device does not pass.
CaseProof proveCase(const Case& c, unsigned threads = 0);

}  // namespace rayspec
