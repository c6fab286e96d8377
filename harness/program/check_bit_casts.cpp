#include "program/check_bit_casts.h"

#include <map>
#include <set>
#include <string>

#include "program/locals.h"
#include "program/ops.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

using Computed = std::map<std::string, bool>;  // local -> holds a device-computed value

// Float built-ins that return what the case (or the shader) passed, unchanged.
bool passedThrough(Builtin b, Stage stage) {
  switch (b) {
    case kBiTmin:
    case kBiWorldOrigin:
    case kBiWorldDirection:
    case kBiQTmin:
    case kBiQWorldOrigin:
    case kBiQWorldDirection:
      return true;
    case kBiTmax:  // the trace's own only where no hit has shortened it
      return stage == Stage::Miss;
    default:
      return false;
  }
}

// Ops whose Float result rounds (or may be fused, or folded in another precision).
bool rounds(const std::string& op) {
  static const std::set<std::string> ops = {
      "add",         "sub",        "mul",         "div",        "dot",
      "cross",       "length",     "normalize",   "mat3_mul",   "mat3_tmul",
      "sphere_near", "sphere_far", "light_point", "light_spot", "light_directional"};
  return ops.count(op) > 0;
}

// Float and the vectors: the sized floats' arithmetic is exact (the model
// names an inexact result a case error), so every device gives its bits.
bool isFloat(ValueType t) {
  return t != ValueType::Uint && t != ValueType::Bool && !isSized(t);
}

bool deviceComputed(const Expr& e, Stage stage, const Computed& locals) {
  switch (e.kind) {
    case Expr::Kind::Literal:
    case Expr::Kind::Constant:
    case Expr::Kind::RecordMember:
      return false;
    case Expr::Kind::Builtin:
      return isFloat(e.type) && !passedThrough(e.builtin, stage);
    case Expr::Kind::Local: {
      const auto it = locals.find(e.name);
      return it == locals.end() || it->second;  // a parameter: whatever its caller passed
    }
    case Expr::Kind::Op:
      break;
  }
  if (isFloat(e.type) && rounds(e.name)) return true;
  for (const Expr& a : e.args)
    if (deviceComputed(a, stage, locals)) return true;
  return false;
}

// Every local's assignments, then the least fixed point of "computed".
Computed computedLocals(const Program& p, Stage stage) {
  std::multimap<std::string, const Expr*> assigned;
  Computed locals;
  walkStatements(p, [&](const Stmt& s) {
    if (s.kind == Stmt::Kind::Let || s.kind == Stmt::Kind::Set)
      for (const auto& [name, value] : s.assigns) assigned.emplace(name, &value);
    if (s.kind == Stmt::Kind::Store && !s.assigns.empty())
      assigned.emplace(s.local, &s.assigns[0].second);
    if (s.kind == Stmt::Kind::Array || s.kind == Stmt::Kind::Repeat) locals[s.local] = false;
    if (s.kind == Stmt::Kind::Struct)
      for (const auto& [member, type] : s.params) locals[memberLocal(s.local, member)] = false;
  });
  for (const auto& [name, value] : assigned) locals[name] = false;
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [name, value] : assigned)
      if (!locals[name] && deviceComputed(*value, stage, locals)) changed = locals[name] = true;
  }
  return locals;
}

}  // namespace

std::optional<ProgramError> checkBitCasts(const Program& p, Stage stage) {
  const Computed locals = computedLocals(p, stage);
  std::optional<ProgramError> error;
  walkExpressions(p, [&](const Expr& e) {
    if (error || e.kind != Expr::Kind::Op || e.op != Op::FloatBits || e.args.size() != 1) return;
    if (!deviceComputed(e.args[0], stage, locals)) return;
    error = ProgramError{
        "'float_bits' of a Float the device computes is not portable: its bits depend on the "
        "device's float algorithm (division or reciprocal, FMA or not), which the model cannot "
        "reproduce bit for bit; record the Float itself (compared within its tolerance), or "
        "take the bits of a value the case gives (a literal, a constant, a ray parameter as "
        "passed)",
        e.loc};
  });
  return error;
}

}  // namespace rayspec
