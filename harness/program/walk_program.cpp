#include "program/walk_program.h"

namespace rayspec {
namespace {

// One walker for const and mutable programs: P is Program or const Program,
// E is Expr or const Expr.
template <typename E, typename Visit>
void walkExpr(E& e, const Visit& visit) {
  visit(e);
  for (auto& a : e.args) walkExpr(a, visit);
}

template <typename L, typename Visit>
void walkList(L& list, const Visit& visit) {
  for (auto& e : list) walkExpr(e, visit);
}

template <typename S, typename Visit>
void ownExpressions(S& s, const Visit& visit) {
  for (auto& [field, value] : s.assigns) walkExpr(value, visit);
  switch (s.kind) {
    case Stmt::Kind::If:
    case Stmt::Kind::Switch:
      walkExpr(s.cond, visit);
      break;
    case Stmt::Kind::Repeat:
      walkExpr(s.count, visit);
      walkExpr(s.from, visit);
      break;
    case Stmt::Kind::Store:
      walkExpr(s.index, visit);
      break;
    case Stmt::Kind::Report:
      walkExpr(s.t, visit);
      walkExpr(s.hit_kind, visit);
      walkList(s.attribute, visit);
      break;
    case Stmt::Kind::Call:
      walkExpr(s.call_index, visit);
      break;
    case Stmt::Kind::Generate:
      walkExpr(s.t, visit);
      break;
    case Stmt::Kind::RayQuery:
    case Stmt::Kind::RestartQuery:
    case Stmt::Kind::RecordMiss:
    case Stmt::Kind::RecordHit:
    case Stmt::Kind::Trace: {
      auto& t = s.trace;
      for (auto* list : {&t.origin, &t.direction, &t.tmin, &t.tmax, &t.flags, &t.cull_mask,
                         &t.sbt_offset, &t.sbt_stride, &t.miss, &t.tlas_index})
        walkList(*list, visit);
      break;
    }
    default:
      break;
  }
}

template <typename P, typename Visit>
void statements(P& p, const Visit& visit) {
  for (auto& s : p) {
    visit(s);
    statements(s.then_, visit);
    statements(s.else_, visit);
  }
}

}  // namespace

bool mayEndProgram(const Stmt& s) {
  bool ends = false;
  auto visit = [&](const Stmt& x) {
    ends = ends || x.kind == Stmt::Kind::Ignore || x.kind == Stmt::Kind::Terminate ||
           x.kind == Stmt::Kind::Return;
  };
  visit(s);
  statements(s.then_, visit);
  statements(s.else_, visit);
  return ends;
}

bool leavesQueryLoop(const Program& block) {
  for (const Stmt& s : block) {
    if (s.kind == Stmt::Kind::Break) return true;
    if (s.kind == Stmt::Kind::If && (leavesQueryLoop(s.then_) || leavesQueryLoop(s.else_)))
      return true;
    if (s.kind == Stmt::Kind::RayQuery && leavesQueryLoop(s.else_)) return true;
    if (s.kind == Stmt::Kind::RayQueries)
      for (const Stmt& q : s.then_)
        if (leavesQueryLoop(q.else_)) return true;
  }
  return false;
}

void walkStatements(const Program& p, const std::function<void(const Stmt&)>& visit) {
  statements(p, visit);
}

void walkOwnExpressions(const Stmt& s, const std::function<void(const Expr&)>& visit) {
  ownExpressions(s, visit);
}

void walkExpressions(const Program& p, const std::function<void(const Expr&)>& visit) {
  statements(p, [&](const Stmt& s) { ownExpressions(s, visit); });
}

void editExpressions(Program& p, const std::function<void(Expr&)>& visit) {
  statements(p, [&](Stmt& s) { ownExpressions(s, visit); });
}

}  // namespace rayspec
