// The any-hit / intersection protocol: what a traversal and the programs it
// runs on a candidate say to each other. The traversal hands a candidate to
// an intersection program (runIntersection) or to any-hit (runAnyHit); an
// intersection program reports a t (report: R-ISECT-REPORT, its any-hit,
// commit or not, R-TERMINATE) and asks sphere_hit (sphereHitDecision, whose
// answer the exact tier may note as unsure or force). The state of the
// trace between them is the Traversal (traversal.h).
#pragma once

#include <cstddef>
#include <cstdint>

#include "model/launch_state.h"
#include "model/model_shared.h"
#include "model/model_stage_env.h"
#include "model/model_trace_context.h"

namespace rayspec {

struct Traversal;
class StageInterpreter;

// Whether a report's or generate's t is a sphere root (sphere_near, sphere_far).
inline bool isSphereRoot(const CStmt& s) {
  return s.t.kind == Expr::Kind::Op && (s.t.op == Op::SphereNear || s.t.op == Op::SphereFar);
}

class HitProtocol {
 public:
  HitProtocol(const ModelShared& shared, LaunchState& state, StageInterpreter& interp)
      : sh_(shared), st_(state), interp_(interp) {}
  // An AABB candidate's intersection program (R-TMAX-VIEW: it sees the
  // closest t so far); its reports decide.
  void runIntersection(Traversal& tr, const ModelCandidate& cand, size_t k, bool opaque,
                       const SbtRecord* rec, const CHitGroup* grp);
  // Runs any-hit `p` for a candidate, marked, and again (AnyHitRepeat,
  // R-AHIT-DUP) where its geometry lacks NO_DUPLICATE_ANY_HIT_INVOCATION and
  // the first run did not terminate: the second run's answer stands.
  Flow runAnyHit(const CProgram& p, StageEnv& a, const HitView& hv, uint32_t geometry_flags);
  // reportIntersectionEXT in the intersection program of env.traversal.
  Flow report(const CStmt& s, StageEnv& env);
  // sphere_hit of the candidate `h` that `tr` decides (an intersection
  // program's own box, or a ray_query's AABB candidate): the model's value,
  // or the forced one of a what-if run; notes an unsure decision (exact tier).
  bool sphereHitDecision(Traversal& tr, const HitView& h, bool model_value, float disc);

  // Ray queries (hit_protocol_query.cpp): a candidate offered to its block
  // (kind: a triangle's facing hit kind), the statements of the blocks, and
  // a triangle committed.
  void runQueryCandidate(Traversal& tr, const ModelCandidate& cand, size_t k, bool opaque,
                         uint32_t kind);
  void confirm(StageEnv& env);                   // rayQueryConfirmIntersectionEXT
  void generate(const CStmt& s, StageEnv& env);  // rayQueryGenerateIntersectionEXT
  void terminateQuery(StageEnv& env);            // rayQueryTerminateEXT
  void commitQueryTriangle(Traversal& tr, const ModelCandidate& cand, uint32_t kind);

 private:
  // Whether a reported t becomes a candidate hit (report's first step).
  bool reportInside(const CStmt& s, StageEnv& env, Traversal& tr, float t);
  void noteMissedBox(const CStmt& s, const Traversal& tr) const;
  // runAnyHit's run, and again as AnyHitRepeat says.
  Flow runAnyHitRepeated(const CProgram& p, StageEnv& a, const HitView& hv,
                         uint32_t geometry_flags);
  // Exact tier: notes a box's leading report (Traversal::lead_reports).
  void noteLeadReport(const CStmt& s, const StageEnv& env, Traversal& tr, float t) const;
  // An accepted report committed: the hit hv at t, its kind (report's last step).
  void reportedAttribute(const CStmt& s, StageEnv& env, HitView& hv);
  void commitReport(const CStmt& s, StageEnv& env, Traversal& tr, const HitView& hv, float t,
                    uint32_t kind);
  // R-PREC: how far a device's sphere root (a report's t) may lie from the
  // model's, for the hit h.
  void endOnFirstHit(Traversal& tr) const;
  double sphereRootError(const CStmt& s, const HitView& h, const TraceRay& ray) const;

  const ModelShared& sh_;
  LaunchState& st_;
  StageInterpreter& interp_;
};

}  // namespace rayspec
