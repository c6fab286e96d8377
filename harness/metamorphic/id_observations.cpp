#include "metamorphic/id_observations.h"

#include <algorithm>
#include <array>

#include "program/ops.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

// The id built-in and a ray query's getters of it (candidate.*, committed.*).
std::array<Builtin, 3> readsOf(Builtin id) {
  switch (id) {
    case kBiPrimitive:
      return {id, kBiQCandPrimitive, kBiQCommittedPrimitive};
    case kBiInstance:
      return {id, kBiQCandInstance, kBiQCommittedInstance};
    default:
      return {id, id, id};
  }
}

struct Observer {
  const std::string name;  // the id's record field (the built-in's name)
  const std::array<Builtin, 3> reads;
  IdObservations& out;

  // The built-in, or a ray query's getter of it.
  bool isId(const Expr& e) const {
    return e.kind == Expr::Kind::Builtin &&
           std::find(reads.begin(), reads.end(), e.builtin) != reads.end();
  }
  static bool isUintLiteral(const Expr& e) {
    return e.kind == Expr::Kind::Literal && e.literal.size() == 1 && e.literal[0] >= 0 &&
           e.literal[0] == static_cast<double>(static_cast<uint64_t>(e.literal[0])) &&
           e.type != ValueType::Float;
  }

  // A comparison of the id with a literal: which side of it the id lies.
  bool comparison(const Expr& e) {
    if (e.args.size() != 2 || !isComparison(e.op)) return false;
    const bool left = isId(e.args[0]) && isUintLiteral(e.args[1]);
    const bool right = isId(e.args[1]) && isUintLiteral(e.args[0]);
    if (!left && !right) return false;
    const uint64_t v = static_cast<uint64_t>((left ? e.args[1] : e.args[0]).literal[0]);
    if (e.op == Op::Eq || e.op == Op::Ne) {
      out.equals.push_back(v);
      return true;
    }
    // id < v, id <= v (id < v + 1), v < id (not id < v + 1), v <= id (not id < v): one threshold
    // each.
    const bool id_first = left;
    const bool strict = e.op == Op::Lt || e.op == Op::Gt;
    const bool less_than = (e.op == Op::Lt || e.op == Op::Le) == id_first;  // id on the small side
    out.below.push_back(less_than == strict ? v : v + 1);
    return true;
  }

  void expr(const Expr& e) {
    if (isId(e)) {
      out.exact = true;
      return;
    }
    if (e.kind != Expr::Kind::Op) return;
    if ((e.op == Op::Odd || e.op == Op::Even) && e.args.size() == 1 && isId(e.args[0])) {
      out.parity = true;
      return;
    }
    if (comparison(e)) return;
    for (const Expr& a : e.args) expr(a);
  }

  void exprs(const std::vector<Expr>& v) {
    for (const Expr& e : v) expr(e);
  }

  void program(const Program& p) {
    for (const Stmt& s : p) {
      for (const auto& [field, value] : s.assigns) {
        // Recorded as itself: the harness maps it back.
        if (s.kind == Stmt::Kind::Record && field == name && isId(value)) continue;
        expr(value);
      }
      if (s.kind == Stmt::Kind::If || s.kind == Stmt::Kind::Switch) expr(s.cond);
      if (s.kind == Stmt::Kind::Repeat) {
        expr(s.count);
        expr(s.from);
      }
      if (s.kind == Stmt::Kind::Store) expr(s.index);
      if (s.kind == Stmt::Kind::Report) {
        expr(s.t);
        expr(s.hit_kind);
        exprs(s.attribute);
      }
      if (s.kind == Stmt::Kind::Call) expr(s.call_index);
      if (s.kind == Stmt::Kind::Generate) expr(s.t);
      if (s.kind == Stmt::Kind::Trace || s.kind == Stmt::Kind::RayQuery ||
          s.kind == Stmt::Kind::RestartQuery)
        for (const std::vector<Expr>* a :
             {&s.trace.origin, &s.trace.direction, &s.trace.tmin, &s.trace.tmax, &s.trace.flags,
              &s.trace.cull_mask, &s.trace.sbt_offset, &s.trace.sbt_stride, &s.trace.miss})
          exprs(*a);
      program(s.then_);
      program(s.else_);
    }
  }
};

}  // namespace

std::vector<uint64_t> IdObservations::classOf(uint64_t id) const {
  std::vector<uint64_t> key;
  key.push_back(parity ? id & 1 : 0);
  for (uint64_t v : equals) key.push_back(id == v);
  for (uint64_t t : below) key.push_back(id < t);
  return key;
}

IdObservations observeId(const Pipeline& p, Builtin id) {
  IdObservations out;
  Observer o{builtinSpelling(id), readsOf(id), out};
  const auto observe = [&](const Program& prog) {
    o.program(prog);
    // A hit recorded by hand (record_hit) names its instance, geometry and
    // primitive by index: no id may move.
    walkStatements(prog, [&](const Stmt& s) { out.exact |= s.kind == Stmt::Kind::RecordHit; });
  };
  observe(p.raygen);
  for (const Program& m : p.miss) observe(m);
  for (const HitGroup& g : p.hit_groups)
    for (const std::optional<Program>* prog : {&g.closest_hit, &g.any_hit, &g.intersection})
      if (*prog) observe(**prog);
  for (const Program& k : p.callables) observe(k);
  return out;
}

}  // namespace rayspec
