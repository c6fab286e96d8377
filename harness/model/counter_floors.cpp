// Exact tier: the least a device may count in any-hit and intersection
// programs and in ray query candidate blocks on a clear trace
// (LaunchState::ray_floors, Results::counter_floors). Candidate order is
// unspecified (R-ORDER-UNSPEC) and either program may run again for a
// primitive (R-ISECT-MULTI, R-AHIT-DUP), so a count has no upper bound; but
// on a trace that nothing ends early the interval only shrinks to the
// committed t, so whatever lies clearly before it is offered in every order:
// - each box the ray clearly enters there runs its intersection program
//   (R-AABB-CONS); a non-opaque box's any-hit runs for its program's leading
//   report (leadingReport: made on every run, at a t no order moves) where
//   that t lies clearly inside [tmin, committed t) (R-ISECT-REPORT), and for
//   the committed report (R-AHIT-CLOSEST);
// - each non-opaque triangle hit there runs its any-hit, as the committed
//   hit's own programs ran (R-ISECT-CLOSEST, R-AHIT-CLOSEST);
// - a ray query whose blocks neither end nor restart its loop offers each
//   such box and non-opaque triangle to its block (R-RQ-CANDIDATES).
// Each such run counts what its program's (block's) leading `count`
// statements count.
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

// What one candidate's runs count: a hit group's programs, or a ray query's
// blocks (no any-hit for an AABB: its generate commits).
struct FloorRuns {
  const std::vector<int>* box = nullptr;       // intersection program, AABB block
  const std::vector<int>* triangle = nullptr;  // any-hit, triangle block
  const std::vector<int>* report = nullptr;    // the any-hit of a box's report
};

FloorRuns groupRuns(const CHitGroup& g) {
  FloorRuns r;
  if (g.intersection) r.box = &g.intersection_leading;
  if (g.any_hit) r.triangle = r.report = &g.any_hit_leading;
  return r;
}

struct QueryBlocks {
  std::vector<int> triangle, box;
  explicit QueryBlocks(const QueryRun* q) {
    if (!q || q->stmt->then_.size() < 2) return;
    triangle = leadingCounts(q->stmt->then_[0].then_);
    box = leadingCounts(q->stmt->then_[1].then_);
  }
  FloorRuns runs() const { return {&box, &triangle, nullptr}; }
};

// Where an interval [start, end) holds a t that a device may move by err,
// clear of both ends on every device.
struct FloorSpan {
  double start = 0, end = 0;
  bool holds(double t, double err) const { return t - err > start && t + err < end; }
};

// A query whose blocks neither end nor restart its loop, in a stage that runs
// alike on every device for a clear ray (not in an any-hit or intersection
// program, whose runs the order and duplicates decide).
bool queryFloorsHold(const QueryRun& q) {
  if (!q.stmt || !q.env || queryBlocksMayEnd(*q.stmt)) return false;
  return q.env->stage != Stage::AnyHit && q.env->stage != Stage::Intersection;
}

// The first leading report of candidate k the model's run made, if any.
const LeadReport* leadOf(const std::vector<LeadReport>& leads, size_t k) {
  for (const LeadReport& l : leads)
    if (l.k == k) return &l;
  return nullptr;
}

// A box: its intersection program (AABB block) where every device enters it,
// and a non-opaque box's any-hit for its committed report and its leading one.
void countBoxFloors(const Traversal& tr, const ModelCandidate& cand, bool opaque,
                    const FloorRuns& runs, const FloorSpan& span, const LeadReport* lead,
                    std::vector<uint64_t>& floors) {
  const bool committed = isCommitted(tr.best, cand);
  // The part of the interval where the ray is inside the box shrunk by
  // the device's error bound: entered there on every device.
  const double lo = std::max(cand.inner_t0, span.start), hi = std::min(cand.inner_t1, span.end);
  const bool entered = !cand.near_face && lo + tr.tol(lo) < hi - tr.tol(hi);
  if (runs.box && (entered || committed)) countRun(*runs.box, floors);
  if (opaque || !runs.report) return;
  // A committed report of a non-opaque box ran its any-hit.
  if (committed) countRun(*runs.report, floors);
  // Its leading report, clearly inside the interval in every order: any-hit runs.
  if ((entered || committed) && lead && span.holds(lead->t, tr.tol(lead->t) + lead->err))
    countRun(*runs.report, floors);
}

// A non-opaque triangle hit, facing the ray: its any-hit (triangle block)
// where it lies clearly before the committed t, or is the committed hit.
void countTriangleFloor(const Traversal& tr, const ModelCandidate& cand, const FloorRuns& runs,
                        const FloorSpan& span, std::vector<uint64_t>& floors) {
  const double tol = tr.endTol(cand);
  const bool inside = cand.t > span.start + tol && cand.t < tr.ray.tmax - tol;
  if (inside && (isCommitted(tr.best, cand) || cand.t < span.end - tol))
    countRun(*runs.triangle, floors);
}

}  // namespace

// Whether every legal order of this trace offers the candidates before its
// committed t: none ends it early (terminate-on-first-hit, an any-hit that
// may terminate, a query block that may end or restart the loop), and the
// launch ray is clear so far.
bool ModelTracer::floorsHold(const Traversal& tr, const std::vector<ModelCandidate>& cands) const {
  if (!tr.exact || tr.stop || st_.ray_ambiguous || st_.ray_undefined) return false;
  if (tr.query && !queryFloorsHold(*tr.query)) return false;
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

void ModelTracer::countFloors(const Traversal& tr, const std::vector<ModelCandidate>& cands,
                              const std::vector<LeadReport>& leads) {
  if (!floorsHold(tr, cands)) return;
  const FloorSpan span{tr.tmin, floorEnd(tr)};
  const QueryBlocks blocks(tr.query);
  for (size_t k = 0; k < cands.size(); ++k) {
    const std::optional<OrderedCandidate> at = candidateAt(tr, cands, k);
    if (!at) continue;  // culled by opacity
    const ModelCandidate& cand = cands[at->k];
    FloorRuns runs = blocks.runs();
    if (!tr.query) {
      const CHitGroup* grp = groupOf(*sh_.programs, sbt_.hit(cand.instance, cand.geometry, tr.ray));
      if (!grp) continue;
      runs = groupRuns(*grp);
    }
    if (cand.aabb) {
      countBoxFloors(tr, cand, at->opaque, runs, span, leadOf(leads, at->k), st_.ray_floors);
    } else if (!at->opaque && runs.triangle && cand.hit && cand.ambiguity == TriAmbiguity::None &&
               !facing(*sh_.scene, cand, tr.ray, tr.flags).culled) {
      countTriangleFloor(tr, cand, runs, span, st_.ray_floors);
    }
  }
}

}  // namespace rayspec
