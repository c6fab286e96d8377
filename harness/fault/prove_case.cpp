// Proving a whole case: the model as the perfect device, each claim proven.
#include "fault/prove_case.h"

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "model/model_engine.h"

namespace rayspec {

bool claimHolds(const ClaimProof& p) {
  return p.result == ClaimResult::Proven || p.result == ClaimResult::NotChecked;
}

const FaultOutcome* provingFault(const ClaimProof& p) {
  const RuleFaults* rf = findRuleFaults(p.rule);
  if (!rf || p.result != ClaimResult::Proven) return nullptr;
  for (const FaultOutcome& o : p.outcomes)
    if (!o.legal && o.changed && o.status == rf->expect && o.names_rule) return &o;
  return nullptr;
}

bool CaseProof::ok() const {
  if (!model.ok() || clean.status != Status::Pass || reversed.status != Status::Pass) return false;
  for (const ClaimProof& p : claims)
    if (!claimHolds(p)) return false;
  return true;
}

CaseProof proveCase(const Case& c, unsigned threads) {
  CaseProof proof;
  proof.plan = derivePlan(c);
  ModelOptions options;
  options.threads = threads;
  proof.model = runOnModel(c, proof.plan, options);
  if (!proof.model.ok()) return proof;
  proof.perfect = perfectDevice(c, proof.model);
  proof.clean = compareResults(c, proof.plan, proof.perfect, proof.model);
  if (proof.clean.status != Status::Pass) return proof;
  for (const std::string& rule : c.rules)
    proof.claims.push_back(proveClaim(c, proof.plan, proof.model, proof.perfect, rule));
  // R-ORDER-UNSPEC for every case: its verdict may not depend on the order
  // candidates are found in (a device finding them far to near passes).
  Results reversed = proof.perfect;
  plantFault("reverse-order", c, proof.plan, reversed, proof.model);
  proof.reversed = compareResults(c, proof.plan, reversed, proof.model);
  return proof;
}

}  // namespace rayspec
