// Exact tier: the least a device may count in any-hit and intersection
// programs on a clear trace (LaunchState::ray_floors, Results::counter_floors).
// Candidate order is unspecified (R-ORDER-UNSPEC) and either program may run
// again for a primitive (R-ISECT-MULTI, R-AHIT-DUP), so a count has no upper
// bound; but on a trace that nothing ends early the interval only shrinks to
// the committed t, so whatever lies clearly before it is offered in every
// order: each box the ray clearly enters there runs its intersection
// program (R-AABB-CONS), each non-opaque triangle hit there its any-hit, as
// the committed hit's own programs ran (R-ISECT-CLOSEST, R-AHIT-CLOSEST).
// Each such run counts what its program's leading `count` statements count.
#include <cmath>

#include "case/flag_names.h"
#include "model/model_tracer.h"
#include "model/traversal.h"

namespace rayspec {

using namespace trace_detail;

namespace {

bool isCommitted(const Committed& best, const ModelCandidate& c) {
  return best.valid && best.instance == c.instance && best.geometry == c.geometry &&
         best.primitive == c.primitive;
}

void countRun(const std::vector<int>& leading, std::vector<uint64_t>& floors) {
  for (int k : leading) floors[static_cast<size_t>(k)] += 1;
}

}  // namespace

// Whether every legal order of this trace offers the candidates before its
// committed t: none ends it early (terminate-on-first-hit, an any-hit that
// may terminate), and the launch ray is clear so far.
bool ModelTracer::floorsHold(const Traversal& tr, const std::vector<ModelCandidate>& cands) const {
  if (!tr.exact || tr.query || tr.stop || st_.ray_ambiguous || st_.ray_undefined) return false;
  if (st_.replay && !st_.replay->own) return false;
  if (tr.flags & kRayTerminateOnFirstHit) return false;
  return !anyHitMayTerminate(tr, cands);
}

// The t below which a candidate is clearly before the committed hit (the
// committed t less its rounding, R-PREC), or clearly inside tmax.
double ModelTracer::floorEnd(const Traversal& tr) const {
  const double tmax = tr.ray.tmax - tr.tol(tr.ray.tmax);
  if (!tr.best.valid) return tmax;
  return std::min(tmax, tr.best.t - tr.tol(tr.best.t) - std::max(tr.best.t_err, 0.0));
}

void ModelTracer::countFloors(const Traversal& tr, const std::vector<ModelCandidate>& cands) {
  if (!floorsHold(tr, cands)) return;
  const double end = floorEnd(tr);
  const double start = tr.tmin;
  for (size_t k = 0; k < cands.size(); ++k) {
    const std::optional<OrderedCandidate> at = candidateAt(tr, cands, k);
    if (!at) continue;  // culled by opacity
    const ModelCandidate& cand = cands[at->k];
    const CHitGroup* grp = groupOf(*sh_.programs, sbt_.hit(cand.instance, cand.geometry, tr.ray));
    if (!grp) continue;
    const bool committed = isCommitted(tr.best, cand);
    if (cand.aabb) {
      // The part of the interval where the ray is inside the box shrunk by
      // the device's error bound: entered there on every device.
      const double lo = std::max(cand.inner_t0, start), hi = std::min(cand.inner_t1, end);
      const bool entered = !cand.near_face && lo + tr.tol(lo) < hi - tr.tol(hi);
      if (grp->intersection && (entered || committed))
        countRun(grp->intersection_leading, st_.ray_floors);
      // A committed report of a non-opaque box ran its any-hit.
      if (committed && !at->opaque && grp->any_hit) countRun(grp->any_hit_leading, st_.ray_floors);
      continue;
    }
    if (at->opaque || !grp->any_hit || !cand.hit || cand.ambiguity != TriAmbiguity::None) continue;
    if (facing(*sh_.scene, cand, tr.ray, tr.flags).culled) continue;
    const double tol = tr.endTol(cand);
    const bool inside = cand.t > start + tol && cand.t < tr.ray.tmax - tol;
    if (inside && (committed || cand.t < end - tol)) countRun(grp->any_hit_leading, st_.ray_floors);
  }
}

}  // namespace rayspec
