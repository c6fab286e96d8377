// The ray query side of the hit protocol (hit_protocol.h): a candidate's
// block runs in the query's frame; confirm, generate and terminate_query
// act on the traversal deciding it (R-RQ-COMMIT, R-RQ-TERMINATE), and a
// break out of its loop ends it.
#include <algorithm>
#include <cmath>
#include <string>

#include "case/flag_names.h"
#include "model/hit_protocol.h"
#include "model/stage_interpreter.h"
#include "model/traversal.h"

namespace rayspec {

using namespace trace_detail;

void HitProtocol::runQueryCandidate(Traversal& tr, const ModelCandidate& cand, size_t k,
                                    bool opaque, uint32_t kind) {
  QueryRun& q = *tr.query;
  HitView hv = viewOf(*sh_.scene, *sh_.c, tr.ray, cand.instance, cand.geometry, cand.primitive);
  if (!cand.aabb) setHit(hv, static_cast<float>(cand.t), kind, cand.b1, cand.b2);
  if (sh_.fault_seam.queryObjectRayWorld()) {  // planted: the world ray as the object ray
    hv.object_origin = {tr.ray.origin[0], tr.ray.origin[1], tr.ray.origin[2]};
    hv.object_direction = {tr.ray.direction[0], tr.ray.direction[1], tr.ray.direction[2]};
  }
  // A nested query's block may run while this one's runs: each keeps its own.
  Traversal* const outer_tr = q.tr;
  const ModelCandidate* const outer_cand = q.cand;
  const HitView outer_view = q.cand_view;
  const bool outer_opaque = q.cand_opaque;
  q.tr = &tr;
  q.cand = &cand;
  q.cand_view = hv;
  q.cand_opaque = opaque;
  tr.cur = &cand;
  tr.cur_index = k;
  tr.sphere_ord = 0;  // its block's sphere_hit decisions (the exact tier's what-if runs)
  if (cand.aabb && tr.reports) tr.reports->push_back({k, NAN});  // it ran (R-TIE's check)
  // The planted fault rq_candidate_type_swapped runs the other kind's block.
  const bool aabb_block = cand.aabb != sh_.fault_seam.queryCandidateTypeSwapped();
  const CProgram& block = q.stmt->then_[aabb_block ? 1 : 0].then_;
  // A break out of the proceed loop: no candidate follows; what is committed
  // so far stays (R-RQ-COMMIT), unless the planted fault loses it.
  if (interp_.exec(block, *q.env) == Flow::Break) {
    tr.stop = true;
    if (sh_.fault_seam.queryBreakLosesCommit()) tr.best = Committed{};
  }
  // Planted: the interval shrinks to the candidate returned, committed or not.
  if (sh_.fault_seam.queryCandidateShrinksInterval()) tr.tmax_cur = std::min(tr.tmax_cur, cand.t);
  tr.cur = nullptr;
  q.tr = outer_tr;
  q.cand = outer_cand;
  q.cand_view = outer_view;
  q.cand_opaque = outer_opaque;
}

// R-RQ-TERMINATE: under TerminateOnFirstHit the first commit ends traversal.
void HitProtocol::endOnFirstHit(Traversal& tr) const {
  if ((tr.flags & kRayTerminateOnFirstHit) && !sh_.fault_seam.queryTerminateIgnored())
    tr.stop = true;
}

void HitProtocol::commitQueryTriangle(Traversal& tr, const ModelCandidate& cand, uint32_t kind) {
  // Exact tier, R-PREC: how far a device's t may lie (its frame's rounding).
  tr.best = {true, cand.t,  cand.instance, cand.geometry, cand.primitive,
             kind, cand.b1, cand.b2,       cand.t_err};
  if (!sh_.fault_seam.queryCommitKeepsInterval()) tr.tmax_cur = cand.t;
  endOnFirstHit(tr);
}

void HitProtocol::confirm(StageEnv& env) {
  QueryRun* q = env.query;
  if (!q || !q->tr || !q->cand || q->cand->aabb) return;
  if (sh_.fault_seam.queryConfirmIgnored()) return;
  if (sh_.fault_seam.queryConfirmOnlyFirst() && q->tr->best.valid) return;
  commitQueryTriangle(*q->tr, *q->cand, q->cand_view.hit_kind);
}

void HitProtocol::generate(const CStmt& s, StageEnv& env) {
  QueryRun* q = env.query;
  if (!q || !q->tr || !q->cand || !q->cand->aabb) return;
  Traversal& tr = *q->tr;
  const Val tv = interp_.eval(s.t, env);
  const float t = s.t.type == ValueType::Uint ? static_cast<float>(tv.u) : tv.f[0];
  // R-RQ-COMMIT: in [tmin, committed t] (the query's tmax before a commit),
  // as the query's getters give them (floats); outside, R-UB.
  const float committed_t = static_cast<float>(tr.tmax_cur);
  if (!(t >= q->ray.tmin && t <= committed_t)) {
    if (!st_.ray_undefined)
      st_.markUndefined(
          UndefinedReason::GenerateOutsideInterval,
          (s.src && !s.src->loc.field.empty() ? s.src->loc.field : std::string("generate")) +
              ": t " + std::to_string(t) + " outside [tmin " + std::to_string(q->ray.tmin) +
              ", committed t " + std::to_string(committed_t) + "]");
    return;
  }
  if (sh_.fault_seam.queryGenerateIgnored()) return;
  noteMissedBox(s, tr);
  if (tr.reports) tr.reports->push_back({tr.cur_index, t});
  const HitView& hv = q->cand_view;
  tr.best = {true, static_cast<double>(t), hv.instance, hv.geometry, hv.primitive, 0, 0, 0};
  // R-PREC: how far a device's root of the candidate's sphere may lie from this one.
  if (tr.exact && isSphereRoot(s)) tr.best.t_err = sphereRootError(s, hv, tr.ray);
  if (!sh_.fault_seam.queryCommitKeepsInterval()) tr.tmax_cur = t;
  endOnFirstHit(tr);
}

void HitProtocol::terminateQuery(StageEnv& env) {
  QueryRun* q = env.query;
  if (!q || !q->tr || sh_.fault_seam.queryTerminateIgnored()) return;
  q->tr->stop = true;  // R-RQ-TERMINATE: what is committed stays; the candidate is not committed
}

}  // namespace rayspec
