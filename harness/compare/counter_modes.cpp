#include "compare/counter_modes.h"

#include "program/ops.h"
#include "program/walk_program.h"

namespace rayspec {

const char* counterModeName(CounterMode m) {
  return nameOf(m);
}

std::map<std::string, CounterMode> counterModes(const Case& c) {
  std::map<std::string, CounterMode> modes;
  for (const std::string& name : c.outputs.counters) modes[name] = CounterMode::Exact;
  auto traversal_dependent = [&](const Program& p) {
    walkStatements(p, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::Count) modes[s.counter] = CounterMode::Informational;
    });
  };
  for (const HitGroup& g : c.pipeline.hit_groups) {
    if (g.any_hit) traversal_dependent(*g.any_hit);
    if (g.intersection) traversal_dependent(*g.intersection);
  }
  // A ray_query's candidate blocks run as often as candidates are offered:
  // in any order, possibly again, beyond the committed t or not (R-RQ-CANDIDATES).
  auto queries = [&](const Program& p) {
    walkStatements(p, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::RayQuery) traversal_dependent(s.then_);
    });
  };
  queries(c.pipeline.raygen);
  for (const Program& p : c.pipeline.miss) queries(p);
  for (const Program& p : c.pipeline.callables) queries(p);
  for (const HitGroup& g : c.pipeline.hit_groups)
    if (g.closest_hit) queries(*g.closest_hit);
  // What the case declares wins.
  for (const auto& [name, mode] : c.outputs.counter_modes) {
    if (mode == "exact") modes[name] = CounterMode::Exact;
    if (mode == "at_least") modes[name] = CounterMode::AtLeast;
    if (mode == "at_most") modes[name] = CounterMode::AtMost;
    if (mode == "informational") modes[name] = CounterMode::Informational;
  }
  return modes;
}

namespace {

bool holdsTraceOrCall(const Stmt& s) {
  bool holds = false;
  walkStatements(s.then_, [&](const Stmt& x) {
    holds = holds || x.kind == Stmt::Kind::Trace || x.kind == Stmt::Kind::Call ||
            x.kind == Stmt::Kind::RayQuery;
  });
  return holds;
}

}  // namespace

std::set<std::string> countersUndefinedRaysMayMove(const Case& c) {
  std::set<std::string> moved;
  auto every = [&](const Program& p) {
    walkStatements(p, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::Count) moved.insert(s.counter);
    });
  };
  const Pipeline& pipe = c.pipeline;
  for (const Program& p : pipe.miss) every(p);
  for (const Program& p : pipe.callables) every(p);
  for (const HitGroup& g : pipe.hit_groups)
    for (const auto* p : {&g.closest_hit, &g.any_hit, &g.intersection})
      if (*p) every(**p);
  bool after_undefined =
      false;  // in program order: a statement where a ray's behaviour may be undefined came first
  walkStatements(pipe.raygen, [&](const Stmt& s) {
    // A repeat runs its body again after its traces and calls; a function's
    // body is walked where it is invoked.
    if (s.kind == Stmt::Kind::Repeat && holdsTraceOrCall(s)) after_undefined = true;
    if (s.kind == Stmt::Kind::Count && after_undefined) moved.insert(s.counter);
    if (s.kind == Stmt::Kind::Trace || s.kind == Stmt::Kind::Call || s.kind == Stmt::Kind::RayQuery)
      after_undefined = true;
    walkOwnExpressions(s, [&](const Expr& e) {
      if (e.kind == Expr::Kind::Op && e.type == ValueType::Uint &&
          (e.op == Op::Div || e.op == Op::Mod))
        after_undefined = true;
    });
  });
  return moved;
}

}  // namespace rayspec
