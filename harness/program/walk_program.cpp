#include "program/walk_program.h"

namespace rayspec {
namespace {

void walkExpr(const Expr& e, const std::function<void(const Expr&)>& visit) {
  visit(e);
  for (const Expr& a : e.args) walkExpr(a, visit);
}

void walkList(const std::vector<Expr>& list, const std::function<void(const Expr&)>& visit) {
  for (const Expr& e : list) walkExpr(e, visit);
}

}  // namespace

void walkStatements(const Program& p, const std::function<void(const Stmt&)>& visit) {
  for (const Stmt& s : p) {
    visit(s);
    walkStatements(s.then_, visit);
    walkStatements(s.else_, visit);
  }
}

void walkOwnExpressions(const Stmt& s, const std::function<void(const Expr&)>& visit) {
  for (const auto& [field, value] : s.assigns) walkExpr(value, visit);
  switch (s.kind) {
    case Stmt::Kind::If:
      walkExpr(s.cond, visit);
      break;
    case Stmt::Kind::Report:
      walkExpr(s.t, visit);
      walkExpr(s.hit_kind, visit);
      walkList(s.attribute, visit);
      break;
    case Stmt::Kind::Call:
      walkExpr(s.call_index, visit);
      break;
    case Stmt::Kind::Trace: {
      const TraceArgs& t = s.trace;
      for (const auto* list : {&t.origin, &t.direction, &t.tmin, &t.tmax, &t.flags, &t.cull_mask,
                               &t.sbt_offset, &t.sbt_stride, &t.miss})
        walkList(*list, visit);
      break;
    }
    default:
      break;
  }
}

void walkExpressions(const Program& p, const std::function<void(const Expr&)>& visit) {
  walkStatements(p, [&](const Stmt& s) { walkOwnExpressions(s, visit); });
}

}  // namespace rayspec
