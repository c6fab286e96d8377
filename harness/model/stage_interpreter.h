// The stage-program interpreter of the model: the meaning of every statement
// and op (program/program.h, ops.h). It reads built-ins through
// ModelBuiltins, writes counters and records to the LaunchState, and leaves
// the rest to the two parts it calls back: a trace statement to ModelTracer
// (trace), a report and sphere_hit in an intersection program to
// HitProtocol (report, sphereHitDecision).
#pragma once

#include <cstdint>

#include "model/launch_state.h"
#include "model/model_builtins.h"
#include "model/model_sbt.h"
#include "model/model_shared.h"
#include "model/model_stage_env.h"
#include "model/model_what_if.h"
#include "model/query_run.h"

namespace rayspec {

class ModelTracer;
class HitProtocol;

// Comparisons of two values of a sized scalar type t (model/sized_ops.cpp).
bool sizedLess(ValueType t, const Val& a, const Val& b);
bool sizedEqual(ValueType t, const Val& a, const Val& b);
// A sized scalar through a slot half its width: its upper half of bits kept,
// the lower half (of a float16's or float64's encoding) zero.
Val halvedSized(const Val& v);
// Each sized member of a payload, callable data or hit attribute halved so.
void halveMembers(SizedSlots& members);
// A sized vector with its components rotated (x takes y's, .., the last x's).
Val rotatedSized(const Val& v);
// A sized scalar or vector of type t whose every lane is one (1 or 1.0).
Val onesSized(ValueType t);

class StageInterpreter {
 public:
  StageInterpreter(const ModelShared& shared, LaunchState& state, const ModelSbt& sbt,
                   const ModelBuiltins& builtins, ModelTracer& tracer, HitProtocol& hits)
      : sh_(shared), st_(state), sbt_(sbt), builtins_(builtins), tracer_(tracer), hits_(hits) {}
  Flow exec(const CProgram& p, StageEnv& env);
  Val eval(const CExpr& e, StageEnv& env);
  // Raygen's program for the current launch ray.
  void runRaygen();

 private:
  // shader_record.NAME: its words in the record data (pipeline.sbt.record_layout).
  static Val recordMember(const CExpr& e, const StageEnv& env);
  Val op(const CExpr& e, StageEnv& env);  // stage_interpreter_ops.cpp
  // The ops op() runs before evaluating arguments (spheres, shader record
  // words, short-circuit and/or); false for any other op.
  bool opOnDemand(const CExpr& e, StageEnv& env, Val& r);
  // add sub mul div mod min max on evaluated arguments.
  Val arithmetic(const CExpr& e, const Val* a);
  // The sized scalars' add sub mul min max, and the conversions (float and
  // uint of a sized scalar, high, int8 .. float64): model/sized_ops.cpp.
  Val sizedArithmetic(const CExpr& e, const Val* a);
  Val convert(const CExpr& e, const Val& a);
  // {i8vec2: ..} .. {f64vec4: ..} and x .. w of a sized vector.
  Val constructSized(const CExpr& e, const Val* a, size_t n) const;
  void inexact(const CExpr& e);  // a sized float result not exact: a case error
  Flow execStmt(const CStmt& s, StageEnv& env);
  void execSet(const CStmt& s, StageEnv& env);      // set payload / set call data
  Flow execControl(const CStmt& s, StageEnv& env);  // let .. return (model_control_flow.cpp)
  // An array's elements before any store: zero (a sized array's the
  // OpConstantNull it is declared with), or under the planted fault
  // sized_null_not_zero one.
  Val zeroElement(const CStmt& s) const;
  Flow execRepeat(const CStmt& s, StageEnv& env);
  Flow execSwitch(const CStmt& s, StageEnv& env);
  Flow execInvoke(const CStmt& s, StageEnv& env);
  void loseLocals(StageEnv& env) const;
  void execCall(const CStmt& s, StageEnv& env);   // executeCallableEXT
  void execTrace(const CStmt& s, StageEnv& env);  // traceRayEXT
  // execute, record_miss, record_empty, reorder (stage_interpreter_hit_object.cpp).
  void execHitObject(const CStmt& s, StageEnv& env);
  void recordHit(const CStmt& s, StageEnv& env, uint32_t depth);  // record_hit
  const std::vector<uint32_t>* recordDataRead(Op n, const StageEnv& env) const;
  Flow execRayQuery(const CStmt& s, StageEnv& env);      // a ray_query statement (model_query.cpp)
  Flow execRayQueries(const CStmt& s, StageEnv& env);    // ray_queries, stepped in turn
  Flow execRestartQuery(const CStmt& s, StageEnv& env);  // restart_query
  // A query as rayQueryInitializeEXT starts it (its ray, where it starts).
  void startQuery(QueryRun& q, const CStmt& s, StageEnv& env);
  // Stepped queries whose blocks share what they write: a case error.
  void steppedOrderDependent(const CStmt& s);
  Payload startPayload(const CStmt& s, StageEnv& env);
  TraceRay tracedRay(const CStmt& s, StageEnv& env);
  void callCallable(uint32_t index, CallData& data, uint32_t depth, const CStmt& site);

  const ModelShared& sh_;
  LaunchState& st_;
  const ModelSbt& sbt_;
  const ModelBuiltins& builtins_;
  ModelTracer& tracer_;
  HitProtocol& hits_;
  // The launch ray's last query's committed intersection: where the planted
  // fault rq_init_keeps_committed starts the next query.
  Committed last_query_;
};

}  // namespace rayspec
