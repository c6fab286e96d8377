#include "program/hit_object.h"

#include "program/builtins.h"
#include "program/walk_program.h"

namespace rayspec {

bool isHitObjectStatement(const Stmt& s) {
  switch (s.kind) {
    case Stmt::Kind::Trace:
      return s.trace.hit_object;
    case Stmt::Kind::ExecuteHitObject:
    case Stmt::Kind::RecordMiss:
    case Stmt::Kind::RecordHit:
    case Stmt::Kind::RecordEmpty:
    case Stmt::Kind::Reorder:
      return true;
    default:
      return false;
  }
}

bool isHitObjectRecordRead(const Expr& e) {
  return e.kind == Expr::Kind::Op &&
         (e.op == Op::HitObjectRecordUint || e.op == Op::HitObjectRecordFloat);
}

bool usesHitObject(const Program& p) {
  bool uses = false;
  walkStatements(p, [&](const Stmt& s) { uses = uses || isHitObjectStatement(s); });
  walkExpressions(p, [&](const Expr& e) {
    uses = uses || isHitObjectRecordRead(e) ||
           (e.kind == Expr::Kind::Builtin && (builtinNeeds(e.builtin) & builtin_needs::HitObject));
  });
  return uses;
}

std::string hitObjectGetterOf(const std::string& name) {
  return name == "hit_t" ? "hit_object.t" : "hit_object." + name;
}

}  // namespace rayspec
