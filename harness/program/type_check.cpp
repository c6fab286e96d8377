// Type inference and validation of stage-program expressions (typeCheck).
// A Uint literal (written without '.') is promoted to Float wherever its
// partner or slot needs a Float, so `{lt: [hit_t, 2]}` means 2.0.
#include <cmath>
#include <string>

#include "program/builtins.h"
#include "program/check_expr.h"
#include "program/constant_value.h"
#include "program/ops.h"

namespace rayspec {
namespace {

bool isVector(ValueType t) {
  return t == ValueType::Vec2 || t == ValueType::Vec3 || t == ValueType::Vec4;
}
bool isScalarNumber(ValueType t) {
  return t == ValueType::Uint || t == ValueType::Float;
}
bool isUintLiteral(const Expr& e) {
  return e.kind == Expr::Kind::Literal && e.type == ValueType::Uint;
}
ValueType vectorOf(int n) {
  return n == 2 ? ValueType::Vec2 : n == 3 ? ValueType::Vec3 : ValueType::Vec4;
}

// Promotes a Uint literal to Float when the other side is Float or a vector.
void unifyLiterals(Expr& a, Expr& b) {
  if ((b.type == ValueType::Float || isVector(b.type)) && isUintLiteral(a))
    a.type = ValueType::Float;
  if ((a.type == ValueType::Float || isVector(a.type)) && isUintLiteral(b))
    b.type = ValueType::Float;
}

std::string typeList(const std::vector<Expr>& args) {
  std::string s;
  for (size_t i = 0; i < args.size(); ++i) {
    if (i) s += ", ";
    s += valueTypeName(args[i].type);
  }
  return s;
}

ProgramError err(const Expr& e, const std::string& msg) {
  return {msg, e.loc};
}

std::optional<ProgramError> checkLiteral(Expr& e) {
  const size_t n = e.literal.size();
  if (n < 1 || n > 4 || static_cast<size_t>(componentCount(e.type)) != n)
    return err(e, "malformed literal (" + std::to_string(n) + " components, type " +
                      valueTypeName(e.type) + ")");
  if (e.type == ValueType::Uint) {
    double v = e.literal[0];
    if (!(v >= 0 && v <= 4294967295.0) || v != std::floor(v))
      return err(e, "Uint literal out of range 0..4294967295");
  }
  return std::nullopt;
}

std::optional<ProgramError> checkOp(Expr& e, Stage stage, const OpInfo& op) {
  const std::string name = e.name;
  auto& a = e.args;
  const int n = static_cast<int>(a.size());
  if (!(op.stages & stageBit(stage)))
    return err(e, "operator '" + name + "' is not available in " + stageName(stage));
  if (n < op.min_args || n > op.max_args) {
    std::string want = op.min_args == op.max_args
                           ? std::to_string(op.min_args)
                           : std::to_string(op.min_args) + ".." + std::to_string(op.max_args);
    return err(e,
               "operator '" + name + "' takes " + want + " argument(s), got " + std::to_string(n));
  }
  for (Expr& arg : a)
    if (auto r = checkExpr(arg, stage)) return r;
  auto bad = [&](const std::string& need) {
    return err(e, "operator '" + name + "': arguments are (" + typeList(a) + "); " + need);
  };

  if (name == "add" || name == "sub" || name == "mul" || name == "div") {
    unifyLiterals(a[0], a[1]);
    ValueType t0 = a[0].type, t1 = a[1].type;
    if (t0 == t1 && t0 != ValueType::Bool) {
      e.type = t0;
    } else if (isVector(t0) && t1 == ValueType::Float) {
      e.type = t0;
    } else if (t0 == ValueType::Float && isVector(t1)) {
      e.type = t1;
    } else {
      return bad("need the same numeric type, or a Float with a vector");
    }
    if (name == "div" && e.type == ValueType::Uint && constantUint(a[1]) == 0u)
      return err(e, "operator 'div': Uint division by a constant zero (undefined behaviour, R-UB)");
    return std::nullopt;
  }
  if (name == "mod") {
    if (a[0].type != ValueType::Uint || a[1].type != ValueType::Uint) return bad("need Uint, Uint");
    if (constantUint(a[1]) == 0u)
      return err(e, "operator 'mod': Uint modulo by a constant zero (undefined behaviour, R-UB)");
    e.type = ValueType::Uint;
    return std::nullopt;
  }
  if (name == "min" || name == "max") {
    unifyLiterals(a[0], a[1]);
    if (a[0].type != a[1].type || a[0].type == ValueType::Bool)
      return bad("need the same numeric type");
    e.type = a[0].type;
    return std::nullopt;
  }
  if (name == "eq" || name == "ne" || name == "lt" || name == "le" || name == "gt" ||
      name == "ge") {
    unifyLiterals(a[0], a[1]);
    if (a[0].type != a[1].type || !isScalarNumber(a[0].type))
      return bad("need the same scalar type (Uint or Float)");
    e.type = ValueType::Bool;
    return std::nullopt;
  }
  if (name == "and" || name == "or" || name == "not") {
    for (const Expr& x : a)
      if (x.type != ValueType::Bool) return bad("need Bool");
    e.type = ValueType::Bool;
    return std::nullopt;
  }
  if (name == "odd" || name == "even") {
    if (a[0].type != ValueType::Uint) return bad("need Uint");
    e.type = ValueType::Bool;
    return std::nullopt;
  }
  if (name == "float") {
    if (a[0].type != ValueType::Uint) return bad("need Uint");
    e.type = ValueType::Float;
    return std::nullopt;
  }
  if (name == "uint") {
    if (a[0].type != ValueType::Float) return bad("need Float");
    e.type = ValueType::Uint;
    return std::nullopt;
  }
  if (name == "vec2" || name == "vec3" || name == "vec4") {
    const int size = name[3] - '0';
    if (n != 1 && n != size)
      return err(e, "operator '" + name + "' takes 1 (splat) or " + std::to_string(size) +
                        " Float arguments, got " + std::to_string(n));
    for (Expr& x : a) {
      if (isUintLiteral(x)) x.type = ValueType::Float;
      if (x.type != ValueType::Float) return bad("need Float scalars");
    }
    e.type = vectorOf(size);
    return std::nullopt;
  }
  if (name == "x" || name == "y" || name == "z" || name == "w") {
    const int index = name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : 3;
    if (!isVector(a[0].type) || componentCount(a[0].type) <= index)
      return bad("need a vector with a ." + name + " component");
    e.type = ValueType::Float;
    return std::nullopt;
  }
  if (name == "dot") {
    if (!isVector(a[0].type) || a[0].type != a[1].type)
      return bad("need two vectors of the same size");
    e.type = ValueType::Float;
    return std::nullopt;
  }
  if (name == "length" || name == "normalize") {
    if (!isVector(a[0].type)) return bad("need a vector");
    e.type = name == "length" ? ValueType::Float : a[0].type;
    return std::nullopt;
  }
  if (name == "sphere_hit") {
    e.type = ValueType::Bool;
    return std::nullopt;
  }
  if (name == "sphere_near" || name == "sphere_far") {
    e.type = ValueType::Float;
    return std::nullopt;
  }
  if (name.rfind("light_", 0) == 0) {
    if (a[0].type != ValueType::Vec3 || a[1].type != ValueType::Vec3)
      return bad("need a Vec3 position and a Vec3 normal");
    e.type = ValueType::Vec4;
    return std::nullopt;
  }
  if (name == "shader_record_uint" || name == "shader_record_float") {
    if (!isUintLiteral(a[0]) || a[0].literal[0] > 7)
      return err(e, "operator '" + name + "' takes a Uint literal word index 0..7");
    e.type = name == "shader_record_uint" ? ValueType::Uint : ValueType::Float;
    return std::nullopt;
  }
  return err(e, "operator '" + name + "' has no typing rule");
}

}  // namespace

std::optional<ProgramError> checkExpr(Expr& e, Stage stage) {
  switch (e.kind) {
    case Expr::Kind::Literal:
      return checkLiteral(e);
    case Expr::Kind::Builtin: {
      const BuiltinInfo* b = findBuiltin(e.name);
      if (!b) return err(e, "unknown built-in '" + e.name + "'");
      if (!(b->stages & stageBit(stage)))
        return err(e, "built-in '" + e.name + "' cannot be read in " + stageName(stage));
      e.type = b->type;
      return std::nullopt;
    }
    case Expr::Kind::Op: {
      const OpInfo* op = findOp(e.name);
      if (!op) return err(e, "unknown operator '" + e.name + "'");
      return checkOp(e, stage, *op);
    }
  }
  return err(e, "malformed expression");
}

std::optional<ProgramError> checkExprAs(Expr& e, Stage stage, ValueType want,
                                        const std::string& what) {
  if (auto r = checkExpr(e, stage)) return r;
  if (want == ValueType::Float && isUintLiteral(e)) e.type = ValueType::Float;
  if (e.type != want)
    return err(e, what + ": expected " + valueTypeName(want) + ", got " + valueTypeName(e.type));
  return std::nullopt;
}

std::string typeCheck(Expr& e, Stage stage) {
  auto r = checkExpr(e, stage);
  return r ? r->message : std::string();
}

}  // namespace rayspec
