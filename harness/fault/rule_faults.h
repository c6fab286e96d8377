// Which planted faults stand for a device breaking which rule: the proof
// that a case's rule claim is not hollow. A case may claim a rule only if
// one of the rule's breaking faults, planted in a perfect device's results
// (the model's own, see perfectDevice), makes the comparison give `expect`;
// and no legal variation the rule allows may make it fail. Rules that only
// grant a freedom (R-ISECT-MULTI) are proven by a legal variation that finds
// something to vary in the case and still passes; so is a case where none of
// a rule's breaking faults applies (R-AHIT-DUP on geometry without
// no_duplicate_any_hit, where nothing is forbidden, only allowed).
#pragma once

#include <string>
#include <vector>

#include "base/enum_names.h"
#include "case/case.h"
#include "compare/verdict.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

struct RuleFaults {
  std::string rule;
  std::vector<std::string> breaks;  // faults of a device breaking the rule
  std::vector<std::string> legal;   // variations the rule allows a device
  Status expect = Status::Fail;     // QualityWarning for a "should" rule
  std::string pending;              // no fault yet: why (and whose)
  std::vector<std::string> live;    // Vulkan faults that break it on a live device only
};

// One entry per rule of references/spec-rules.yaml (rule_faults.cpp).
const std::vector<RuleFaults>& ruleFaults();
const RuleFaults* findRuleFaults(const std::string& rule);

// The rules whose entry names fault `fault`: as a break (breaks or live) or as
// a variation the rule allows (legal). Both empty: a fault of the run itself
// (a crash, a lost device), which breaks no rule of the catalog.
struct RulesOfFault {
  std::vector<std::string> breaks, allows;
};
RulesOfFault rulesOfFault(const std::string& fault);

struct FaultOutcome {
  std::string fault;
  bool legal = false;    // a legal variation, not a break
  bool applied = false;  // the fault found something to change
  bool changed = false;  // the device's results differ from the perfect device's
  Status status = Status::Pass;
  bool names_rule = false;  // a finding of that status names the rule
  std::string what;         // what the fault did, or why it did not apply
  std::string headline;     // the verdict's
  std::string claim_line;   // the finding naming the rule (claimLine): what a proof shows
};

// Whether a finding of the verdict's own status names `rule` (a proof's
// "the fault broke that rule", FaultOutcome::names_rule).
bool namesRule(const Verdict& v, const std::string& rule);
// The finding of the verdict's own status a proof of `rule` shows: the first
// whose label names the rule, else the first evidence against it; null when
// none names it.
const Finding* findingNaming(const Verdict& v, const std::string& rule);
// That finding's line, "(evidence against R-X)" added where its label names
// other rules; "" when none names the rule.
std::string claimLine(const Verdict& v, const std::string& rule);

#define RAYSPEC_CLAIM_RESULTS(X)                                                       \
  /* a break gives `expect` (and no legal variation fails) */                          \
  X(Proven, "proven")                                                                  \
  /* no break changes the verdict: nothing shows the rule is checked */                \
  X(Hollow, "hollow")                                                                  \
  /* a legal variation fails: the case depends on a freedom of the rule */             \
  X(FailsLegal, "fails a legal device")                                                \
  X(Pending, "pending")          /* the rule has no fault yet (RuleFaults::pending) */ \
  X(NotChecked, "not checked")   /* R-UB: never checked for a result */                \
  X(UnknownRule, "unknown rule") /* not in the table */
enum class ClaimResult { RAYSPEC_CLAIM_RESULTS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(ClaimResult, RAYSPEC_CLAIM_RESULTS);
inline const char* claimResultName(ClaimResult r) {
  return nameOf(r);
}

struct ClaimProof {
  std::string rule;
  ClaimResult result = ClaimResult::Hollow;
  std::string note;
  std::vector<FaultOutcome> outcomes;
  std::string describe() const;  // one line per fault
};

// Plants every fault of the rule in `perfect` (a device whose results pass:
// perfectDevice(c, model)) and judges each against `model`.
ClaimProof proveClaim(const Case& c, const Plan& plan, const Results& model, const Results& perfect,
                      const std::string& rule);

}  // namespace rayspec
