// ray_query statements in the model (R-RQ-*): the query's ray traversed as a
// trace's (model_traversal.cpp: Embree's candidates sorted, the exact tier's
// what-if runs), its candidates decided by its blocks instead of any-hit and
// intersection programs (HitProtocol::runQueryCandidate); no shader runs.
// A triangle block is an any-hit whose default is ignore (only confirm
// commits), an AABB block an intersection program whose generate always
// commits; opaque triangles commit without being offered.
#include "case/flag_names.h"
#include "model/hit_protocol.h"
#include "model/model_tracer.h"
#include "model/order_dependence.h"
#include "model/stage_interpreter.h"
#include "model/traversal.h"

namespace rayspec {

using namespace trace_detail;

void StageInterpreter::startQuery(QueryRun& q, const CStmt& s, StageEnv& env) {
  q.stmt = &s;
  q.env = &env;
  q.outer = env.query;
  q.level = env.query ? env.query->level + 1 : 0;
  q.ray = tracedRay(s, env);
  q.may_terminate = s.size != 0;
  if (sh_.fault_seam.queryInitKeepsCommitted()) q.start = last_query_;
}

// The query's fields as a trace's (tracedRay: the launch ray's in raygen),
// its traversal, then `after` with what stays committed.
Flow StageInterpreter::execRayQuery(const CStmt& s, StageEnv& env) {
  QueryRun q;
  startQuery(q, s, env);
  env.query = &q;
  tracer_.rayQuery(q, &s);
  last_query_ = q.committed;
  const Flow f = exec(s.else_, env);
  env.query = q.outer;
  return f;
}

// ray_queries: every query initialized in order, then (on a device) stepped
// in turn, one candidate each, until all are done, then each one's `after`.
// The model runs each query's traversal whole, one after another: the same
// answers wherever no query's blocks write what another's read or write
// (steppedQueriesShare; otherwise the interleaving decides, and the case is
// refused), as each block then sees only its own query and what its own
// blocks left.
Flow StageInterpreter::execRayQueries(const CStmt& s, StageEnv& env) {
  if (s.order_dependent) steppedOrderDependent(s);
  std::vector<QueryRun> qs(s.then_.size());
  for (size_t i = 0; i < qs.size(); ++i) startQuery(qs[i], s.then_[i], env);
  // The planted fault rq_step_wrong_query: each query decides the next one's candidates.
  if (sh_.fault_seam.queryStepWrongQuery() && qs.size() > 1) {
    const TraceRay first = qs[0].ray;
    for (size_t i = 0; i + 1 < qs.size(); ++i) qs[i].ray = qs[i + 1].ray;
    qs.back().ray = first;
  }
  QueryRun* const outer = env.query;
  for (size_t i = 0; i < qs.size(); ++i) {
    env.query = &qs[i];
    tracer_.rayQuery(qs[i], &s.then_[i]);
    last_query_ = qs[i].committed;
  }
  for (size_t i = 0; i < qs.size(); ++i) {
    env.query = &qs[i];
    const Flow f = exec(s.then_[i].else_, env);
    env.query = outer;
    if (f != Flow::Continue) return f;
  }
  env.query = outer;
  return Flow::Continue;
}

void StageInterpreter::steppedOrderDependent(const CStmt& s) {
  const OrderDependence d = steppedQueriesShare(s);
  st_.orderDependent("the ray_queries at " + statementPlace(&s) + " (" + d.why + ")",
                     ": the interleaving of candidates between queries stepped in turn is "
                     "unspecified, and the model runs each query whole; let each query's "
                     "blocks write only locals of their own (or merge them after the loop)");
}

// restart_query (R-RQ-INIT: initializing discards all previous state): the
// innermost query's traversal stops with nothing committed, and
// ModelTracer::rayQuery runs the new ray's with the same blocks; the block
// ends (the GLSL's continue). Past kMaxQueryRestarts it does nothing, as the
// GLSL's count, and the case is an error (endless restarts).
Flow StageInterpreter::execRestartQuery(const CStmt& s, StageEnv& env) {
  QueryRun* q = env.query;
  if (!q || !q->tr) return Flow::Continue;
  if (q->restarts >= kMaxQueryRestarts) {
    st_.endlessRestarts("the restart_query at " + statementPlace(&s),
                        ": launch ray " + std::to_string(st_.index) + " restarts its query " +
                            "more than " + std::to_string(kMaxQueryRestarts) + " times");
    return Flow::Continue;
  }
  q->restarts += 1;
  Traversal& tr = *q->tr;
  const Committed keep = sh_.fault_seam.queryRestartKeepsCommitted() ? tr.best : Committed{};
  q->restart = QueryRestart{tracedRay(s, env), keep, &s};
  tr.best = Committed{};  // what the stopped traversal leaves: nothing (the restart's keep)
  tr.stop = true;
  return Flow::Next;
}

void ModelTracer::rayQuery(QueryRun& q, const CStmt* site) {
  for (;;) {
    // R-RQ-INIT, R-UB: a ray with a non-finite, NaN or negative parameter
    // finds nothing (traverse keeps it from Embree).
    st_.checkRayParameters(q.ray, site, 1);
    Payload none;  // a query passes no payload
    q.restart.reset();
    q.committed = traverse(q.ray, q.ray.flags, 1, none, &q);
    q.tr = nullptr;
    if (!q.restart) return;
    // A restart: the same blocks decide the new ray's candidates.
    q.ray = q.restart->ray;
    q.start = q.restart->keep;
    site = q.restart->site;
  }
}

// As decide() (model_traversal.cpp) orders and filters candidates: masks and
// culling by Embree and here, the interval as for a trace (R-RQ-CANDIDATES).
void ModelTracer::decideQuery(Traversal& tr, const std::vector<ModelCandidate>& cands,
                              const int8_t* force) {
  const ModelScene& scene = *sh_.scene;
  for (size_t pos = 0; pos < cands.size(); ++pos) {
    if (tr.stop) break;
    const std::optional<OrderedCandidate> at = candidateAt(tr, cands, pos);
    if (!at) continue;
    const size_t k = at->k;
    const bool opaque = at->opaque;
    const ModelCandidate& cand = cands[k];
    if (cand.aabb) {
      if (!boxOffered(cand, k, force)) continue;
      // A box entered beyond the committed t may or may not be offered: the
      // model offers none (a preferred one at the committed t still is).
      if (cand.t > tr.tmax_cur && !(tr.prefer == static_cast<long>(k) && tr.ties(cand.t))) continue;
      hits_.runQueryCandidate(tr, cand, k, opaque, 0);
      continue;
    }
    if (!(force && force[k] >= 0 ? force[k] == 1 : cand.hit)) continue;
    if (!triangleInside(tr, cand, k, force)) continue;
    const Facing f = facing(scene, cand, tr.ray, tr.flags);
    if (f.culled) continue;
    if (!opaque || sh_.fault_seam.queryOffersOpaque()) {
      hits_.runQueryCandidate(tr, cand, k, opaque, f.kind);
      continue;
    }
    hits_.commitQueryTriangle(tr, cand, f.kind);
  }
}

}  // namespace rayspec
