// Proving one rule claim of a case: every fault of the rule planted in a
// perfect device's results, each judged.
#include <sstream>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "fault/rule_faults.h"

namespace rayspec {

const Finding* findingNaming(const Verdict& v, const std::string& rule) {
  for (const Finding& f : v.findings)
    if (f.status == v.status && labelNames(f, rule)) return &f;
  for (const Finding& f : v.findings)
    if (f.status == v.status && findingNames(f, rule)) return &f;
  return nullptr;
}

bool namesRule(const Verdict& v, const std::string& rule) {
  return findingNaming(v, rule) != nullptr;
}

std::string claimLine(const Verdict& v, const std::string& rule) {
  const Finding* f = findingNaming(v, rule);
  if (!f) return {};
  return findingLine(*f) + (labelNames(*f, rule) ? "" : " (evidence against " + rule + ")");
}

namespace {

FaultOutcome plant(const std::string& fault, bool legal, const Case& c, const Plan& plan,
                   const Results& model, const Results& perfect, const std::string& rule) {
  FaultOutcome o;
  o.fault = fault;
  o.legal = legal;
  Results device = perfect;
  const FaultResult f = plantFault(fault, c, plan, device, model);
  o.applied = f.applied;
  o.what = f.what;
  if (!f.applied) return o;
  o.changed = !sameOutput(device, perfect);
  const Verdict v = compareResults(c, plan, device, model);
  o.status = v.status;
  o.names_rule = namesRule(v, rule);
  o.headline = v.headline();
  o.claim_line = claimLine(v, rule);
  return o;
}

}  // namespace

std::string ClaimProof::describe() const {
  std::ostringstream s;
  s << rule << ": " << claimResultName(result);
  if (!note.empty()) s << " (" << note << ")";
  for (const FaultOutcome& o : outcomes) {
    s << "\n    " << (o.legal ? "legal " : "break ") << o.fault << ": ";
    if (!o.applied)
      s << "not applicable: " << o.what;
    else if (!o.changed)
      s << "changed nothing (" << o.what << ")";
    else
      s << (o.names_rule ? o.claim_line : o.headline + " [no finding names the rule]");
  }
  return s.str();
}

ClaimProof proveClaim(const Case& c, const Plan& plan, const Results& model, const Results& perfect,
                      const std::string& rule) {
  ClaimProof p;
  p.rule = rule;
  const RuleFaults* rf = findRuleFaults(rule);
  if (!rf) {
    p.result = ClaimResult::UnknownRule;
    return p;
  }
  if (rule == "R-UB" || !rf->pending.empty()) {
    p.result = rule == "R-UB" ? ClaimResult::NotChecked : ClaimResult::Pending;
    p.note = rf->pending;
    return p;
  }
  bool broken = false, exercised = false, varied = false, break_applied = false;
  for (const std::string& f : rf->breaks) {
    p.outcomes.push_back(plant(f, false, c, plan, model, perfect, rule));
    const FaultOutcome& o = p.outcomes.back();
    // Proven only by the verdict a break should give, with a finding that names the rule.
    broken = broken || (o.changed && o.status == rf->expect && o.names_rule);
    break_applied = break_applied || o.applied;
  }
  for (const std::string& f : rf->legal) {
    p.outcomes.push_back(plant(f, true, c, plan, model, perfect, rule));
    const FaultOutcome& o = p.outcomes.back();
    if (o.applied && o.status != Status::Pass) {
      p.result = ClaimResult::FailsLegal;
      p.note = "the legal variation " + f + " gives " + statusName(o.status);
      return p;
    }
    exercised = exercised || o.applied;
    varied = varied || (o.applied && o.changed);
  }
  // Where no break applies (R-AHIT-DUP without the flag: nothing is
  // forbidden), the claim is that the case tolerates the rule's freedom: a
  // legal variation must change the device's results, and still pass.
  const bool proven = rf->breaks.empty() ? exercised : break_applied ? broken : varied;
  p.result = proven ? ClaimResult::Proven : ClaimResult::Hollow;
  if (!proven)
    p.note = rf->breaks.empty() ? "no legal variation finds anything to vary"
                                : std::string("no break gives ") + statusName(rf->expect) +
                                      " with a finding naming " + rule;
  return p;
}

}  // namespace rayspec
