// The stage-program interpreter of the model (stage_interpreter.h): the
// meaning of every statement (program/program.h); ops in
// stage_interpreter_ops.cpp, built-ins in model_builtins.cpp, control flow
// in model_control_flow.cpp.
#include "model/stage_interpreter.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "model/hit_protocol.h"
#include "model/model_shading.h"
#include "model/model_tracer.h"

namespace rayspec {
namespace {

float bitsf(uint32_t u) {
  return std::bit_cast<float>(u);
}

}  // namespace

// A member of the shader record block: its words from e.index on, as its
// type (a word past the record's data reads 0).
Val StageInterpreter::recordMember(const CExpr& e, const StageEnv& env) {
  auto word = [&](uint32_t k) {
    const uint32_t i = e.index + k;
    return env.record_data && i < env.record_data->size() ? (*env.record_data)[i] : 0u;
  };
  if (e.type == ValueType::Uint) return fromUint(word(0));
  Val r;
  for (int k = 0; k < componentCount(e.type); ++k) r.f[k] = bitsf(word(k));
  return r;
}

Val StageInterpreter::eval(const CExpr& e, StageEnv& env) {
  switch (e.kind) {
    case Expr::Kind::Literal:
    case Expr::Kind::Constant:  // compiled to a literal (model_program.cpp)
      return e.literal;
    case Expr::Kind::Builtin:
      return builtins_.read(e, env);
    case Expr::Kind::Op:
      return op(e, env);
    case Expr::Kind::Local:
      return e.index < env.locals.size() ? env.locals[e.index] : Val{};
    case Expr::Kind::RecordMember:
      return recordMember(e, env);
  }
  return Val{};
}

Flow StageInterpreter::exec(const CProgram& p, StageEnv& env) {
  for (const CStmt& s : p) {
    const Flow f = execStmt(s, env);
    if (f != Flow::Continue) return f;
  }
  return Flow::Continue;
}

Flow StageInterpreter::execStmt(const CStmt& s, StageEnv& env) {
  switch (s.kind) {
    case Stmt::Kind::Count:
      if (s.counter >= 0) st_.counters[s.counter] += 1;
      return Flow::Continue;
    case Stmt::Kind::Record:
      if (!st_.rec) return Flow::Continue;
      for (const CAssign& a : s.assigns) st_.record(a.field, eval(a.value, env), a.value.type);
      return Flow::Continue;
    case Stmt::Kind::SetPayload:
    case Stmt::Kind::SetCall:
      execSet(s, env);
      return Flow::Continue;
    case Stmt::Kind::Ignore:
      return Flow::Ignore;
    case Stmt::Kind::Terminate:
      return Flow::Terminate;
    case Stmt::Kind::If:
      return exec(eval(s.cond, env).b ? s.then_ : s.else_, env);
    case Stmt::Kind::Light: {
      if (!env.call) return Flow::Continue;
      static const std::vector<uint32_t> kEmpty;
      const Vec3 p = env.call->position, n = env.call->normal;
      env.call->color = lightColor(s.light, p, n, env.record_data ? *env.record_data : kEmpty);
      return Flow::Continue;
    }
    case Stmt::Kind::Call:
      execCall(s, env);
      loseLocals(env);
      return Flow::Continue;
    case Stmt::Kind::Trace:
      execTrace(s, env);
      loseLocals(env);
      return Flow::Continue;
    case Stmt::Kind::ExecuteHitObject:
    case Stmt::Kind::RecordMiss:
    case Stmt::Kind::RecordEmpty:
    case Stmt::Kind::RecordHit:
    case Stmt::Kind::Reorder:
      execHitObject(s, env);
      return Flow::Continue;
    case Stmt::Kind::Report: {
      const Flow f = hits_.report(s, env);
      loseLocals(env);
      return f;
    }
    case Stmt::Kind::RayQuery:
      return execRayQuery(s, env);
    case Stmt::Kind::RayQueries:
      return execRayQueries(s, env);
    case Stmt::Kind::RestartQuery:
      return execRestartQuery(s, env);
    case Stmt::Kind::Confirm:
      hits_.confirm(env);
      return Flow::Continue;
    case Stmt::Kind::Generate:
      hits_.generate(s, env);
      return Flow::Continue;
    case Stmt::Kind::TerminateQuery:
      hits_.terminateQuery(env);
      return Flow::Continue;
    case Stmt::Kind::Candidates:  // run by its ray_query's traversal only
      return Flow::Continue;
    default:
      return execControl(s, env);
  }
  return Flow::Continue;
}

// The planted fault locals_lost_across_calls: a device that does not keep a
// shader's live values across a trace, call or report reads them as zero.
// The planted fault sized_locals_halved: a sized scalar or vector local
// (int8 .. f64vec4) keeps only the upper half of its bits; sized_vectors_rotated:
// a sized vector's components come back rotated.
void StageInterpreter::loseLocals(StageEnv& env) const {
  if (sh_.fault_seam.localsLostAcrossCalls())
    std::fill(env.locals.begin(), env.locals.end(), Val{});
  if (sh_.fault_seam.sizedLocalsHalvedAcrossCalls())
    for (Val& v : env.locals)
      if (isSized(v.sized)) v = halvedSized(v);
  if (sh_.fault_seam.sizedVectorsRotatedAcrossCalls())
    for (Val& v : env.locals)
      if (isSizedVector(v.sized)) v = rotatedSized(v);
}

namespace {

// One assignment into a payload or callable data: color and value, for a
// payload its words, and for callable data also position and normal.
template <typename Data>
void writeSlot(Data& d, const CAssign& a, const Val& v) {
  const Slot slot = a.slot;
  if (slot == Slot::Color) d.color = v.f;
  if (slot == Slot::Value) d.value = v.u;
  if constexpr (requires { d.words; }) {
    if (slot == Slot::Word) d.words[a.word % kMaxPayloadWords] = v.u;
  }
  if (slot == Slot::Sized) d.sized.write(static_cast<ValueType>(a.word), v);
  if constexpr (requires { d.position; }) {
    if (slot == Slot::Position) d.position = {v.f[0], v.f[1], v.f[2]};
    if (slot == Slot::Normal) d.normal = {v.f[0], v.f[1], v.f[2]};
  }
}

}  // namespace

void StageInterpreter::execSet(const CStmt& s, StageEnv& env) {
  for (const CAssign& a : s.assigns) {
    const Val v = eval(a.value, env);
    if (s.kind == Stmt::Kind::SetPayload && env.payload)
      writeSlot(*env.payload, a, v);
    else if (s.kind == Stmt::Kind::SetCall && env.call)
      writeSlot(*env.call, a, v);
  }
}

void StageInterpreter::execCall(const CStmt& s, StageEnv& env) {
  CallData d;
  for (const CAssign& a : s.assigns) writeSlot(d, a, eval(a.value, env));
  if (s.src) d.location = s.src->call_location;
  callCallable(eval(s.call_index, env).u, d, env.depth, s);
  if (sh_.fault_seam.sizedCallDataHalvedAcrossCall()) halveMembers(d.sized);
  env.callee = d;
}

// The ray a trace statement traces: the launch ray (raygen) or the case's
// defaults for nested traces, with what the statement gives.
TraceRay StageInterpreter::tracedRay(const CStmt& s, StageEnv& env) {
  const bool from_launch = env.stage == Stage::Raygen;
  TraceRay r = launchRay(from_launch ? sh_.c->rays.launchRay(st_.index) : sh_.c->rays.defaults);
  auto v3 = [&](int k, Vec3& out) {
    if (s.has[k]) {
      const Val v = eval(s.args[k], env);
      out = {v.f[0], v.f[1], v.f[2]};
    }
  };
  auto f1 = [&](int k, float& out) {
    if (s.has[k]) {
      const Val v = eval(s.args[k], env);
      out = s.args[k].type == ValueType::Uint ? static_cast<float>(v.u) : v.f[0];
    }
  };
  auto u1 = [&](int k, uint32_t& out) {
    if (s.has[k]) out = eval(s.args[k], env).u;
  };
  v3(CStmt::kOrigin, r.origin);
  v3(CStmt::kDirection, r.direction);
  f1(CStmt::kTmin, r.tmin);
  f1(CStmt::kTmax, r.tmax);
  u1(CStmt::kFlags, r.flags);
  u1(CStmt::kCullMask, r.cull_mask);
  u1(CStmt::kSbtOffset, r.sbt_offset);
  u1(CStmt::kSbtStride, r.sbt_stride);
  u1(CStmt::kMiss, r.miss);
  if (s.src) r.tlas = s.src->trace.tlas;
  // A dynamic index wraps as an array local's does (the GLSL takes it % N too).
  if (s.has[CStmt::kTlas]) r.tlas = eval(s.args[CStmt::kTlas], env).u % sh_.c->scene.tlasCount();
  return r;
}

// The payload a trace starts with: what the statement gives, zero elsewhere.
Payload StageInterpreter::startPayload(const CStmt& s, StageEnv& env) {
  Payload p;
  for (const CAssign& a : s.assigns) writeSlot(p, a, eval(a.value, env));
  if (s.src) p.location = s.src->trace.location;
  return p;
}

void StageInterpreter::execTrace(const CStmt& s, StageEnv& env) {
  TraceRay r = tracedRay(s, env);
  const Payload start = startPayload(s, env);
  const uint32_t depth = env.stage == Stage::Raygen ? 1 : env.depth + 1;
  if (depth > std::max<uint32_t>(sh_.c->pipeline.max_recursion, 1)) {
    // R-RECURSION, R-UB: the ray is undefined; the model skips the trace
    // (no traversal, no shader, the stage's child payload stays as it was).
    if (!st_.ray_undefined)
      st_.markUndefined(
          UndefinedReason::RecursionTooDeep,
          (s.src && !s.src->loc.field.empty() ? s.src->loc.field : std::string("trace")) +
              ": trace at depth " + std::to_string(depth) + " exceeds pipeline.max_recursion " +
              std::to_string(sh_.c->pipeline.max_recursion));
    return;
  }
  Payload p = s.src && s.src->trace.hit_object && env.hit_object
                  ? tracer_.traceIntoHitObject(r, depth, &s, start, *env.hit_object)
                  : tracer_.trace(r, depth, &s, start);
  if (sh_.fault_seam.sizedPayloadHalvedAcrossTrace()) halveMembers(p.sized);
  if (env.stage == Stage::Raygen && env.payload)
    *env.payload = p;
  else
    env.child = p;
}

// R-UB: an index beyond the callable region, or callables nested beyond the
// pipeline's stack (R-STACK), make the ray undefined; the model then skips the call (the
// data stays as the caller wrote it).
void StageInterpreter::callCallable(uint32_t index, CallData& data, uint32_t depth,
                                    const CStmt& site) {
  auto field = [&](const char* sub) {
    const std::string f =
        site.src && !site.src->loc.field.empty() ? site.src->loc.field : std::string("call");
    return f + sub;
  };
  if (index >= sbt_.callables().size()) {
    if (!st_.ray_undefined)
      st_.markUndefined(UndefinedReason::CallableOutOfRange,
                        field(".index") + ": callable " + std::to_string(index) + ", the SBT has " +
                            std::to_string(sbt_.callables().size()));
    return;
  }
  const Pipeline& p = sh_.c->pipeline;
  if (st_.call_nesting >= p.callableDepth()) {
    if (!st_.ray_undefined)
      st_.markUndefined(
          UndefinedReason::RecursionTooDeep,
          field("") + ": callables nested " + std::to_string(st_.call_nesting + 1) + " deep, the " +
              (p.callable_depth ? "stack size set" : "default stack") +
              " (pipeline.callable_depth) holds " + std::to_string(p.callableDepth()));
    return;
  }
  if (st_.call_nesting >= kDefaultCallableDepth && sh_.fault_seam.stackSizeIgnored()) return;
  const SbtRecord& rec = sbt_.callables()[index];
  if (!rec.group || *rec.group >= sh_.c->pipeline.callables.size()) return;  // R-SBT-ZERO
  const uint32_t own = p.callableData(*rec.group);
  if (p.callDataWords(own) != p.callDataWords(data.location) ||
      p.callDataSized(own) != p.callDataSized(data.location))
    st_.callDataTypeDiffers(data, *rec.group);
  st_.bumpRuns(kRunsCallable);
  StageEnv env;
  env.stage = Stage::Callable;
  env.record_data = &rec.data;
  env.call = &data;
  env.depth = depth;
  ++st_.call_nesting;
  exec(sh_.programs->callables[*rec.group], env);
  --st_.call_nesting;
}

void StageInterpreter::runRaygen() {
  last_query_ = {};
  StageEnv env;
  env.stage = Stage::Raygen;
  env.record_data = &sh_.c->pipeline.raygen_data;
  Payload last;
  env.payload = &last;
  HitObjectState hit_object;
  env.hit_object = &hit_object;
  exec(sh_.programs->raygen, env);
}

}  // namespace rayspec
