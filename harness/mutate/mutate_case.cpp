#include "mutate/mutate_case.h"

#include <chrono>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"

#include "mutate/legal_survival.h"
#include "mutate/planted_mutants.h"

namespace rayspec {
namespace {

MutantOutcome judgeMutant(const MutantInput& in, const GenericMutant& g, const Results& device) {
  MutantOutcome o;
  o.kind = g.kind;
  o.name = g.name;
  Results mutated = device;
  o.mutation = g.apply(in, g.target, mutated);
  if (o.mutation.applied && sameOutput(mutated, device)) {
    o.mutation.applied = false;
    o.mutation.what = "changed nothing: " + o.mutation.what;
  }
  if (!o.mutation.applied) return o;
  const Verdict v = compareResults(in.c, in.plan, mutated, in.model);
  o.status = v.status;
  o.headline = v.headline();
  o.killed = isFailing(v.status);
  if (!o.killed) o.legal_reason = legalSurvival(in, g, o.mutation, mutated);
  return o;
}

}  // namespace

CaseMutation mutateCase(const Case& c, const Plan& plan, const Results& device,
                        const Results& model, unsigned threads) {
  CaseMutation out;
  out.name = c.name;
  out.family = c.family;
  // A case the checks refuse (order-dependent, not portable) is refused on
  // every device, the model's own included: its legal devices would only
  // repeat the refusal, each counted a false alarm.
  const Verdict refused = compareResults(c, plan, perfectDevice(c, model), model);
  if (refused.status == Status::CaseError) {
    out.not_judged = "refused on every device: " + refused.headline();
    return out;
  }
  const auto start = std::chrono::steady_clock::now();
  out.legal_devices = judgeLegalDevices(c, plan, model, threads);
  const auto legal_done = std::chrono::steady_clock::now();
  out.legal_seconds = std::chrono::duration<double>(legal_done - start).count();
  const Verdict unmutated = compareResults(c, plan, device, model);
  if (unmutated.status != Status::Pass && unmutated.status != Status::QualityWarning) {
    out.not_judged = "the device results as saved: " + unmutated.headline();
    return out;
  }
  out.judged = true;
  const MutantInput in{c, plan, model};
  for (const GenericMutant& g : genericMutants(c, device))
    out.mutants.push_back(judgeMutant(in, g, device));
  for (MutantOutcome& o : judgePlantedFaults(c, plan, model)) out.mutants.push_back(std::move(o));
  out.mutant_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - legal_done).count();
  return out;
}

}  // namespace rayspec
