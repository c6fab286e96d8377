// One ray_query statement while the model runs it (StageInterpreter starts
// it, ModelTracer traverses, HitProtocol runs its candidate blocks and
// commits, ModelBuiltins reads its getters). Its blocks run in the frame of
// the stage that holds it (env): its locals, payload and records.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "model/model_stage_env.h"
#include "model/model_trace_context.h"
#include "model/model_what_if.h"

namespace rayspec {

struct Traversal;

// A restart_query of a candidate block (R-RQ-INIT: initializing discards
// all previous state): the query's traversal stops and a new one of `ray`
// starts with `keep` committed (nothing; the planted fault
// rq_restart_keeps_committed keeps the old commit).
struct QueryRestart {
  TraceRay ray;
  Committed keep;
  const CStmt* site = nullptr;
};
inline bool sameRay(const TraceRay& a, const TraceRay& b) {
  return a.origin == b.origin && a.direction == b.direction && a.tmin == b.tmin &&
         a.tmax == b.tmax && a.flags == b.flags && a.cull_mask == b.cull_mask && a.tlas == b.tlas;
}

// The part of a query's frame its blocks may change, kept so that a what-if
// run of the exact tier can run them again from where traversal began: the
// stage's, and the query's pending restart and restart count.
struct QueryFrameSaved {
  std::vector<Val> locals;
  Payload payload;
  Payload child;
  CallData callee;
  std::optional<QueryRestart> restart;
  uint32_t restarts = 0;
};
struct QueryRun {
  const CStmt* stmt = nullptr;  // the ray_query (then_: its candidate blocks, else_: after)
  StageEnv* env = nullptr;      // the frame its blocks run in
  QueryRun* outer = nullptr;    // the query around it (env.query before it)
  uint32_t level = 0;           // its nesting depth
  TraceRay ray;                 // as initialized (R-RQ-INIT)
  bool may_terminate = false;   // a candidate block holds terminate_query
  // Where traversal starts: nothing committed (the planted fault
  // rq_init_keeps_committed starts from the previous query's).
  Committed start;
  // While traversal runs: the traversal deciding (the actual one, or a
  // what-if run of the exact tier), and the candidate whose block runs.
  Traversal* tr = nullptr;
  const ModelCandidate* cand = nullptr;
  HitView cand_view;
  bool cand_opaque = false;
  // After traversal: what stays committed.
  Committed committed;
  // Exact tier: the frame as traversal began, where every what-if run of
  // its blocks starts again.
  QueryFrameSaved frame_before;
  // A restart_query while traversal runs (its traversal then stops), and
  // the restarts of this run of the ray_query (at most kMaxQueryRestarts).
  std::optional<QueryRestart> restart;
  uint32_t restarts = 0;
};

inline QueryFrameSaved saveQueryFrame(const QueryRun& q) {
  const StageEnv& e = *q.env;
  return {e.locals, e.payload ? *e.payload : Payload{}, e.child, e.callee, q.restart, q.restarts};
}
inline void restoreQueryFrame(QueryRun& q, const QueryFrameSaved& s) {
  StageEnv& e = *q.env;
  e.locals = s.locals;
  if (e.payload) *e.payload = s.payload;
  e.child = s.child;
  e.callee = s.callee;
  q.restart = s.restart;
  q.restarts = s.restarts;
}

}  // namespace rayspec
