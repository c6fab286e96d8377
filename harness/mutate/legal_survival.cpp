#include "mutate/legal_survival.h"

#include <algorithm>
#include <set>

#include "compare/counter_modes.h"

namespace rayspec {
namespace {

bool everyRayUndefined(const MutantInput& in, const Mutation& m) {
  if (m.rays.empty()) return false;
  std::set<uint32_t> undefined;
  for (const UndefinedRay& u : in.model.undefined) undefined.insert(u.ray);
  return std::all_of(m.rays.begin(), m.rays.end(), [&](uint32_t r) { return undefined.count(r) > 0; });
}

std::string counterReason(const MutantInput& in, const Mutation& m) {
  const auto modes = counterModes(in.c);
  const auto it = modes.find(m.counter);
  if (it == modes.end()) return "";
  if (!in.model.undefined.empty() && countersUndefinedRaysMayMove(in.c).count(m.counter))
    return "R-UB: rays with undefined behaviour may move counter '" + m.counter + "'";
  switch (it->second) {
    case CounterMode::Informational:
      return "counter '" + m.counter +
             "' is counted in any-hit or intersection: its total depends on traversal order and duplicate "
             "invocations (R-ORDER-UNSPEC, R-AHIT-DUP)";
    case CounterMode::AtLeast:
      return m.delta > 0 ? "counter '" + m.counter + "' is at_least: a device may run it more often" : "";
    case CounterMode::AtMost:
      return m.delta < 0 ? "counter '" + m.counter + "' is at_most: a device may run it less often" : "";
    case CounterMode::Exact: return "";
  }
  return "";
}

bool everyGeometryNoDuplicate(const Case& c) {
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries)
      if (!(g.flags & kGeometryNoDuplicateAnyHit)) return false;
  return true;
}

}  // namespace

std::string legalSurvival(const MutantInput& in, const GenericMutant& g, const Mutation& m, const Results&) {
  if (!m.counter.empty()) return counterReason(in, m);
  if (everyRayUndefined(in, m)) return "R-UB: every changed ray has undefined behaviour";
  if (g.kind == "any-hit-extra" && !everyGeometryNoDuplicate(in.c))
    return "R-AHIT-DUP: without NO_DUPLICATE_ANY_HIT_INVOCATION any-hit may run again on a primitive";
  return "";
}

}  // namespace rayspec
