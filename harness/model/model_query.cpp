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
#include "model/stage_interpreter.h"
#include "model/traversal.h"

namespace rayspec {

using namespace trace_detail;

// The query's fields as a trace's (tracedRay: the launch ray's in raygen),
// its traversal, then `after` with what stays committed.
Flow StageInterpreter::execRayQuery(const CStmt& s, StageEnv& env) {
  QueryRun q;
  q.stmt = &s;
  q.env = &env;
  q.outer = env.query;
  q.level = env.query ? env.query->level + 1 : 0;
  q.ray = tracedRay(s, env);
  q.may_terminate = s.size != 0;
  if (sh_.fault_seam.queryInitKeepsCommitted()) q.start = last_query_;
  env.query = &q;
  tracer_.rayQuery(q, &s);
  last_query_ = q.committed;
  const Flow f = exec(s.else_, env);
  env.query = q.outer;
  return f;
}

void ModelTracer::rayQuery(QueryRun& q, const CStmt* site) {
  // R-RQ-INIT, R-UB: a ray with a non-finite, NaN or negative parameter finds
  // nothing (traverse keeps it from Embree).
  st_.checkRayParameters(q.ray, site, 1);
  Payload none;  // a query passes no payload
  q.committed = traverse(q.ray, q.ray.flags, 1, none, &q);
  q.tr = nullptr;
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
      if (force && force[k] == 0) continue;
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
