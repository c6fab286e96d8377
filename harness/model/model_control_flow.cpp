// The model's meaning of the control-flow statements (program/program.h):
// locals, arrays, repeat, break, continue, switch, invoke and return.
#include <algorithm>
#include <optional>

#include "model/query_run.h"
#include "model/stage_interpreter.h"

namespace rayspec {
namespace {

void setLocal(StageEnv& env, size_t slot, const Val& v) {
  if (slot >= env.locals.size()) env.locals.resize(slot + 1);
  env.locals[slot] = v;
}

}  // namespace

Val StageInterpreter::zeroElement(const CStmt& s) const {
  const ValueType t = s.src ? s.src->local_type : ValueType::Uint;
  if (!isSized(t)) return Val{};
  return sh_.fault_seam.sizedNullNotZero() ? onesSized(t) : fromSized(t, 0);
}

namespace {

// A struct's members, zero (the GLSL constructs it from zeros: no null initialiser).
void zeroMembers(const CStmt& s, StageEnv& env) {
  if (s.slot < 0 || !s.src) return;
  for (uint32_t k = 0; k < s.size && k < s.src->params.size(); ++k) {
    const ValueType t = s.src->params[k].second;
    setLocal(env, static_cast<size_t>(s.slot) + k, isSized(t) ? fromSized(t, 0) : Val{});
  }
}

}  // namespace

Flow StageInterpreter::execControl(const CStmt& s, StageEnv& env) {
  switch (s.kind) {
    case Stmt::Kind::Let:
    case Stmt::Kind::Set:
      for (const CAssign& a : s.assigns)
        if (a.field >= 0) setLocal(env, static_cast<size_t>(a.field), eval(a.value, env));
      return Flow::Continue;
    case Stmt::Kind::Array:
      if (s.slot < 0) return Flow::Continue;
      env.locals.resize(std::max(env.locals.size(), static_cast<size_t>(s.slot) + s.size));
      std::fill_n(env.locals.begin() + s.slot, s.size, zeroElement(s));
      return Flow::Continue;
    case Stmt::Kind::Struct:
      zeroMembers(s, env);
      return Flow::Continue;
    case Stmt::Kind::Store: {
      if (s.words) {  // payload.words / call.words
        uint32_t* w = ModelBuiltins::dataWord(*s.words, s.size, eval(s.index, env).u, env);
        const uint32_t v = s.assigns.empty() ? 0u : eval(s.assigns[0].value, env).u;
        if (w) *w = v;
        return Flow::Continue;
      }
      if (s.slot < 0 || s.size == 0 || s.assigns.empty()) return Flow::Continue;
      const uint32_t i = eval(s.index, env).u % s.size;
      setLocal(env, static_cast<size_t>(s.slot) + i, eval(s.assigns[0].value, env));
      return Flow::Continue;
    }
    case Stmt::Kind::Repeat:
      return execRepeat(s, env);
    case Stmt::Kind::Break:
      return Flow::Break;
    case Stmt::Kind::Continue:
      return Flow::Next;
    case Stmt::Kind::Return:
      return Flow::Return;
    case Stmt::Kind::Switch:
      return execSwitch(s, env);
    case Stmt::Kind::Invoke:
      return execInvoke(s, env);
    default:
      return Flow::Continue;
  }
}

// At most kMaxLoopTrips iterations; the variable is from + k in iteration k.
Flow StageInterpreter::execRepeat(const CStmt& s, StageEnv& env) {
  const uint32_t trips = std::min(eval(s.count, env).u, kMaxLoopTrips);
  const uint32_t from = eval(s.from, env).u;
  for (uint32_t k = 0; k < trips; ++k) {
    if (s.slot >= 0) {
      Val v;
      v.u = from + k;
      setLocal(env, static_cast<size_t>(s.slot), v);
    }
    const Flow f = exec(s.then_, env);
    if (f == Flow::Break) break;
    if (f != Flow::Continue && f != Flow::Next) return f;
  }
  return Flow::Continue;
}

// The case whose label is the value, else the default; no fall-through.
Flow StageInterpreter::execSwitch(const CStmt& s, StageEnv& env) {
  const uint32_t v = eval(s.cond, env).u;
  for (const CStmt& c : s.then_)
    if (c.size == v) return exec(c.then_, env);
  return exec(s.else_, env);
}

// The arguments evaluated in the caller's frame, the body in a frame of its
// own; the caller's locals are back as they were afterwards.
Flow StageInterpreter::execInvoke(const CStmt& s, StageEnv& env) {
  std::vector<Val> frame(std::max<size_t>(s.size, s.assigns.size()));
  for (size_t i = 0; i < s.assigns.size(); ++i) frame[i] = eval(s.assigns[i].value, env);
  std::swap(frame, env.locals);
  // A function that takes the caller's query (query: true) acts on it; the
  // planted fault query_function_gets_copy hands it a copy instead, whose
  // confirm, generate and terminate_query reach no traversal.
  QueryRun* const caller_query = env.query;
  std::optional<QueryRun> copy;
  if (s.src && s.src->query_param && env.query && sh_.fault_seam.queryFunctionGetsCopy()) {
    copy = *env.query;
    copy->tr = nullptr;
    env.query = &*copy;
  }
  const Flow f = exec(s.then_, env);
  env.query = caller_query;
  std::swap(frame, env.locals);
  return f == Flow::Return ? Flow::Continue : f;
}

}  // namespace rayspec
