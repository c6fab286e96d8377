#include "mutate/planted_mutants.h"

#include <algorithm>
#include <set>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "mutate/legal_output.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

bool isQueryFault(const FaultInfo& f) {
  return f.kind == FaultKind::CaseMutation && f.name.rfind("query-", 0) == 0 &&
         f.breaks.rfind("legal:", 0) != 0;
}

// The rays whose record differs between a and b (records of the same size).
std::vector<uint32_t> changedRays(const Results& a, const Results& b) {
  std::vector<uint32_t> rays;
  const uint32_t words = recordWords();
  if (a.records.size() != b.records.size() || !words) return rays;
  for (size_t ray = 0; ray < a.records.size() / words; ++ray) {
    const auto* x = a.records.data() + ray * words;
    if (!std::equal(x, x + words, b.records.data() + ray * words))
      rays.push_back(static_cast<uint32_t>(ray));
  }
  return rays;
}

// R-UB only: every changed ray (there being one) has undefined behaviour.
std::string plantedSurvival(const Results& model, const std::vector<uint32_t>& rays) {
  if (rays.empty()) return "";
  std::set<uint32_t> undefined;
  for (const UndefinedRay& u : model.undefined) undefined.insert(u.ray);
  const bool all =
      std::all_of(rays.begin(), rays.end(), [&](uint32_t r) { return undefined.count(r) > 0; });
  return all ? "R-UB: every changed ray has undefined behaviour" : "";
}

}  // namespace

MutantOutcome judgePlantedFault(const Case& c, const Plan& plan, const Results& model,
                                const Results& base, const FaultInfo& f, bool explain) {
  MutantOutcome o;
  o.kind = "planted";
  o.name = "planted:" + f.name;
  Results device = base;
  const FaultResult r = plantFault(f.name, c, plan, device, model);
  o.mutation.what = r.what;
  // A case mutation answers as the model's perfect device on the mutated
  // case, so it changed something only where it differs from that device on
  // the case itself (base may be a real device's other legal answers).
  const Results unchanged = f.kind == FaultKind::CaseMutation ? perfectDevice(c, model) : base;
  o.mutation.applied = r.applied && !sameOutput(device, unchanged);
  if (!o.mutation.applied) {
    if (r.applied) o.mutation.what = "changed nothing: " + r.what;
    return o;
  }
  o.mutation.rays = changedRays(device, unchanged);
  device.backend = "vulkan";
  const Verdict v = compareResults(c, plan, device, model);
  o.status = v.status;
  o.headline = v.headline();
  o.killed = isFailing(v.status);
  if (!explain) return o;
  if (!o.killed) o.legal_reason = plantedSurvival(model, o.mutation.rays);
  if (!o.killed && o.legal_reason.empty())
    o.legal_reason = legalOutput(c, plan, model, base, device, o.mutation.rays);
  return o;
}

std::vector<MutantOutcome> judgePlantedFaults(const Case& c, const Plan& plan,
                                              const Results& model) {
  std::vector<MutantOutcome> out;
  const Results base = perfectDevice(c, model);
  for (const FaultInfo& f : faultTable())
    if (isQueryFault(f)) {
      out.push_back(judgePlantedFault(c, plan, model, base, f, true));
      out.back().kind = "planted-query";
    }
  return out;
}

}  // namespace rayspec
