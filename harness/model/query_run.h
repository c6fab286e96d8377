// One ray_query statement while the model runs it (StageInterpreter starts
// it, ModelTracer traverses, HitProtocol runs its candidate blocks and
// commits, ModelBuiltins reads its getters). Its blocks run in the frame of
// the stage that holds it (env): its locals, payload and records.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/model_stage_env.h"
#include "model/model_trace_context.h"
#include "model/model_what_if.h"

namespace rayspec {

struct Traversal;

// The part of a query's frame its blocks may change, kept so that a what-if
// run of the exact tier can run them again from where traversal began.
struct QueryFrameSaved {
  std::vector<Val> locals;
  Payload payload;
  Payload child;
  CallData callee;
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
};

inline QueryFrameSaved saveQueryFrame(const QueryRun& q) {
  const StageEnv& e = *q.env;
  return {e.locals, e.payload ? *e.payload : Payload{}, e.child, e.callee};
}
inline void restoreQueryFrame(QueryRun& q, const QueryFrameSaved& s) {
  StageEnv& e = *q.env;
  e.locals = s.locals;
  if (e.payload) *e.payload = s.payload;
  e.child = s.child;
  e.callee = s.callee;
}

}  // namespace rayspec
