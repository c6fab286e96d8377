// Type inference and validation of stage-program expressions (typeCheck).
// A Uint literal (written without '.') is promoted to Float wherever its
// partner or slot needs a Float, so `{lt: [hit_t, 2]}` means 2.0.
#include <cmath>
#include <cstdio>
#include <string>

#include "program/builtins.h"
#include "program/check_expr.h"
#include "program/constant_value.h"
#include "program/ops.h"
#include "program/sized_values.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

bool isVector(ValueType t) {
  return t == ValueType::Vec2 || t == ValueType::Vec3 || t == ValueType::Vec4;
}
bool isScalarNumber(ValueType t) {
  return t == ValueType::Uint || t == ValueType::Float || isSizedScalar(t);
}
bool isUintLiteral(const Expr& e) {
  return e.kind == Expr::Kind::Literal && e.type == ValueType::Uint;
}
ValueType vectorOf(int n) {
  return n == 2 ? ValueType::Vec2 : n == 3 ? ValueType::Vec3 : ValueType::Vec4;
}

std::optional<ProgramError> checkLiteral(Expr& e);

// A literal that a sized scalar's partner takes that type: a Uint literal
// next to any sized scalar, a Float literal next to Float16 or Float64 (next
// to a sized vector: its component type).
bool takesSizedType(const Expr& literal, ValueType partner) {
  if (!isSized(partner) || literal.kind != Expr::Kind::Literal) return false;
  return literal.type == ValueType::Uint ||
         (literal.type == ValueType::Float && isSizedFloat(partner));
}

// Promotes a Uint literal to Float when the other side is Float or a
// vector, and a literal to the sized scalar type of the other side
// (checkLiteral then holds it to that type's values).
std::optional<ProgramError> unifyLiterals(Expr& a, Expr& b) {
  if ((b.type == ValueType::Float || isVector(b.type)) && isUintLiteral(a))
    a.type = ValueType::Float;
  if ((a.type == ValueType::Float || isVector(a.type)) && isUintLiteral(b))
    b.type = ValueType::Float;
  for (auto [literal, partner] : {std::pair<Expr*, Expr*>{&a, &b}, {&b, &a}}) {
    if (!takesSizedType(*literal, partner->type)) continue;
    literal->type = sizedComponent(partner->type);
    if (auto r = checkLiteral(*literal)) return r;
  }
  return std::nullopt;
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

// A sized scalar's literal (a Uint or Float literal its partner typed): ""
// when the type holds the value exactly, else why not.
std::string sizedLiteralProblem(ValueType t, double v) {
  const SizedType* s = sizedType(t);
  if (!s) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  const std::string what = std::string(valueTypeName(t)) + " literal " + text;
  if (s->kind == SizedKind::Floating)
    return s->bits == 64 || exactInFloat16(v)
               ? ""
               : what +
                     " is not a Float16 value (11 significant bits, 2^-14 <= |v| <= 65504, "
                     "or 0)";
  const double top = s->bits == 64 ? 9007199254740992.0  // a literal's double holds 2^53
                                   : std::ldexp(1.0, s->bits - (s->kind == SizedKind::Signed));
  if (v < 0 || v >= top || v != std::floor(v))
    return what + " out of range 0.." + std::to_string(static_cast<uint64_t>(top) - 1);
  return "";
}

// An integer literal over 32 bits (Expr::wide): "" where its place is an
// int64 (below 2^63) or a uint64, else why not.
std::string wideLiteralProblem(const Expr& e) {
  const std::string what = "integer literal " + std::to_string(e.wide);
  if (e.type == ValueType::Uint64) return "";
  if (e.type == ValueType::Int64)
    return e.wide >> 63 ? what + " out of range 0..9223372036854775807 (Int64)" : "";
  return what + " does not fit in 32 bits: only an int64 or uint64 value takes one (here " +
         valueTypeName(e.type) + ")";
}

std::optional<ProgramError> checkLiteral(Expr& e) {
  const size_t n = e.literal.size();
  if (n < 1 || n > 4 || static_cast<size_t>(componentCount(e.type)) != n)
    return err(e, "malformed literal (" + std::to_string(n) + " components, type " +
                      valueTypeName(e.type) + ")");
  if (e.wide) {  // still Uint: its place may make it a 64-bit one (checkWideLiterals)
    const std::string why = e.type == ValueType::Uint ? "" : wideLiteralProblem(e);
    return why.empty() ? std::nullopt : std::optional<ProgramError>(err(e, why));
  }
  if (e.type == ValueType::Uint) {
    double v = e.literal[0];
    if (!(v >= 0 && v <= 4294967295.0) || v != std::floor(v))
      return err(e, "Uint literal out of range 0..4294967295");
  }
  if (const std::string why = sizedLiteralProblem(e.type, e.literal[0]); !why.empty())
    return err(e, why);
  return std::nullopt;
}

// An operator's arguments do not fit: names them and what it needs.
ProgramError badArguments(const Expr& e, const std::string& need) {
  return err(e, "operator '" + e.name + "': arguments are (" + typeList(e.args) + "); " + need);
}

using Typing = std::optional<ProgramError>;

// The typing rules, one an operator family; each sets e.type or says why not.
Typing typeArithmetic(Expr& e) {  // add sub mul div
  auto& a = e.args;
  if (auto r = unifyLiterals(a[0], a[1])) return r;
  ValueType t0 = a[0].type, t1 = a[1].type;
  if (t0 == t1 && t0 != ValueType::Bool)
    e.type = t0;
  else if (isVector(t0) && t1 == ValueType::Float)
    e.type = t0;
  else if (t0 == ValueType::Float && isVector(t1))
    e.type = t1;
  else if (isSizedVector(t0) && t1 == sizedComponent(t0))
    e.type = t0;
  else if (isSizedVector(t1) && t0 == sizedComponent(t1))
    e.type = t1;
  else
    return badArguments(e,
                        "need the same numeric type, or a Float with a vector, or a sized "
                        "vector with a scalar of its component type");
  if (e.op == Op::Div && isSized(e.type))
    return badArguments(e,
                        "div is not offered on the sized scalars (not exact in floats; "
                        "signed overflow in integers)");
  if (e.op == Op::Div && e.type == ValueType::Uint && constantUint(a[1]) == 0u)
    return err(e, "operator 'div': Uint division by a constant zero (undefined behaviour, R-UB)");
  return std::nullopt;
}

Typing typeMod(Expr& e) {
  auto& a = e.args;
  if (a[0].type != ValueType::Uint || a[1].type != ValueType::Uint)
    return badArguments(e, "need Uint, Uint");
  if (constantUint(a[1]) == 0u)
    return err(e, "operator 'mod': Uint modulo by a constant zero (undefined behaviour, R-UB)");
  e.type = ValueType::Uint;
  return std::nullopt;
}

Typing typeBitwise(Expr& e) {  // bit_and bit_or bit_xor shl shr
  if (e.args[0].type != ValueType::Uint || e.args[1].type != ValueType::Uint)
    return badArguments(e, "need Uint, Uint");
  e.type = ValueType::Uint;
  return std::nullopt;
}

Typing typeMinMax(Expr& e) {
  auto& a = e.args;
  if (auto r = unifyLiterals(a[0], a[1])) return r;
  if (a[0].type != a[1].type || a[0].type == ValueType::Bool)
    return badArguments(e, "need the same numeric type");
  e.type = a[0].type;
  return std::nullopt;
}

Typing typeComparison(Expr& e) {  // eq ne lt le gt ge
  auto& a = e.args;
  if (auto r = unifyLiterals(a[0], a[1])) return r;
  if (a[0].type != a[1].type || !isScalarNumber(a[0].type))
    return badArguments(e, "need the same scalar type (Uint, Float or a sized scalar)");
  e.type = ValueType::Bool;
  return std::nullopt;
}

Typing typeLogic(Expr& e) {  // and or not
  for (const Expr& x : e.args)
    if (x.type != ValueType::Bool) return badArguments(e, "need Bool");
  e.type = ValueType::Bool;
  return std::nullopt;
}

// One argument of type `from`, a result of type `to` (odd, even, float, uint).
template <ValueType from, ValueType to>
Typing typeUnary(Expr& e) {
  if (e.args[0].type != from) return badArguments(e, std::string("need ") + valueTypeName(from));
  e.type = to;
  return std::nullopt;
}

Typing typeVectorOf(Expr& e) {  // vec2 vec3 vec4
  const int size = 2 + static_cast<int>(e.op) - static_cast<int>(Op::Vec2);
  const int n = static_cast<int>(e.args.size());
  if (n != 1 && n != size)
    return err(e, "operator '" + e.name + "' takes 1 (splat) or " + std::to_string(size) +
                      " Float arguments, got " + std::to_string(n));
  for (Expr& x : e.args) {
    if (isUintLiteral(x)) x.type = ValueType::Float;
    if (x.type != ValueType::Float) return badArguments(e, "need Float scalars");
  }
  e.type = vectorOf(size);
  return std::nullopt;
}

Typing typeComponent(Expr& e) {  // x y z w
  const int index = static_cast<int>(e.op) - static_cast<int>(Op::CompX);
  const ValueType t = e.args[0].type;
  if (!(isVector(t) || isSizedVector(t)) || componentCount(t) <= index)
    return badArguments(e, "need a vector with a ." + e.name + " component");
  e.type = isSizedVector(t) ? sizedComponent(t) : ValueType::Float;
  return std::nullopt;
}

// {i8vec2: ..} .. {f64vec4: ..}: 1 (splat) or n scalars of the component
// type (a literal takes it).
Typing typeConstructSized(Expr& e) {
  const ValueType to = constructorTarget(e.op), component = sizedComponent(to);
  const int size = componentCount(to), n = static_cast<int>(e.args.size());
  if (n != 1 && n != size)
    return err(e, "operator '" + e.name + "' takes 1 (splat) or " + std::to_string(size) + " " +
                      valueTypeName(component) + " arguments, got " + std::to_string(n));
  for (Expr& x : e.args) {
    if (takesSizedType(x, component)) {
      x.type = component;
      if (auto r = checkLiteral(x)) return r;
    }
    if (x.type != component)
      return badArguments(e, std::string("need ") + valueTypeName(component) + " scalars");
  }
  e.type = to;
  return std::nullopt;
}

Typing typeDot(Expr& e) {
  if (!isVector(e.args[0].type) || e.args[0].type != e.args[1].type)
    return badArguments(e, "need two vectors of the same size");
  e.type = ValueType::Float;
  return std::nullopt;
}

Typing typeVec3Only(Expr& e) {  // cross, mat3_mul, mat3_tmul
  for (const Expr& a : e.args)
    if (a.type != ValueType::Vec3) return badArguments(e, "need Vec3 arguments");
  e.type = ValueType::Vec3;
  return std::nullopt;
}

Typing typeVectorTo(Expr& e, ValueType result) {  // length, normalize
  if (!isVector(e.args[0].type)) return badArguments(e, "need a vector");
  e.type = result;
  return std::nullopt;
}

Typing typeFixed(Expr& e, ValueType type) {  // sphere_hit, sphere_near, sphere_far
  e.type = type;
  return std::nullopt;
}

Typing typeLight(Expr& e) {  // light_*
  if (e.args[0].type != ValueType::Vec3 || e.args[1].type != ValueType::Vec3)
    return badArguments(e, "need a Vec3 position and a Vec3 normal");
  e.type = ValueType::Vec4;
  return std::nullopt;
}

Typing typeShaderRecord(Expr& e, ValueType type) {  // shader_record_uint, shader_record_float
  if (!isUintLiteral(e.args[0]) || e.args[0].literal[0] > 7)
    return err(e, "operator '" + e.name + "' takes a Uint literal word index 0..7");
  e.type = type;
  return std::nullopt;
}

// One argument of one of the types `accepted` says yes to, a result of type `to`.
Typing typeFrom(Expr& e, bool (*accepted)(ValueType), const char* need, ValueType to) {
  if (!accepted(e.args[0].type)) return badArguments(e, need);
  e.type = to;
  return std::nullopt;
}

// float: Uint, Float16, Float64. uint: Float, a sized scalar. high: 64-bit integers.
bool convertsToFloat(ValueType t) {
  return t == ValueType::Uint || (isSizedFloat(t) && isSizedScalar(t));
}
bool convertsToUint(ValueType t) {
  return t == ValueType::Float || isSizedScalar(t);
}
bool hasHighWord(ValueType t) {
  return t == ValueType::Int64 || t == ValueType::Uint64;
}

// {int8: x} .. {float64: x}: an integer from Uint or a sized integer, a float
// from Uint, Float or a sized float.
Typing typeConversion(Expr& e) {
  const ValueType to = conversionTarget(e.op), from = e.args[0].type;
  const bool integer = isSizedInteger(to);
  const bool ok = from == ValueType::Uint ||
                  (isSizedScalar(from) && integer == isSizedInteger(from)) ||
                  (!integer && from == ValueType::Float);
  if (!ok)
    return badArguments(
        e, integer ? "need Uint or a sized integer" : "need Uint, Float, Float16 or Float64");
  e.type = to;
  return std::nullopt;
}

// The typing rule of an operator (program/op_table.h's typing column).
Typing typeOp(Expr& e, OpTyping typing) {
  using V = ValueType;
  switch (typing) {
    case OpTyping::Arithmetic:
      return typeArithmetic(e);
    case OpTyping::Modulo:
      return typeMod(e);
    case OpTyping::MinMax:
      return typeMinMax(e);
    case OpTyping::Comparison:
      return typeComparison(e);
    case OpTyping::Logic:
      return typeLogic(e);
    case OpTyping::Bitwise:
      return typeBitwise(e);
    case OpTyping::UintToUint:
      return typeUnary<V::Uint, V::Uint>(e);
    case OpTyping::UintToFloat:
      return typeUnary<V::Uint, V::Float>(e);
    case OpTyping::UintToBool:
      return typeUnary<V::Uint, V::Bool>(e);
    case OpTyping::FloatToUint:
      return typeUnary<V::Float, V::Uint>(e);
    case OpTyping::FloatToFloat:
      return typeUnary<V::Float, V::Float>(e);
    case OpTyping::VectorOf:
      return typeVectorOf(e);
    case OpTyping::Component:
      return typeComponent(e);
    case OpTyping::Dot:
      return typeDot(e);
    case OpTyping::Vec3Only:
      return typeVec3Only(e);
    case OpTyping::Length:
      return typeVectorTo(e, ValueType::Float);
    case OpTyping::Normalize:
      return typeVectorTo(e, e.args[0].type);
    case OpTyping::FixedBool:
      return typeFixed(e, V::Bool);
    case OpTyping::FixedFloat:
      return typeFixed(e, V::Float);
    case OpTyping::RecordWordUint:
      return typeShaderRecord(e, V::Uint);
    case OpTyping::RecordWordFloat:
      return typeShaderRecord(e, V::Float);
    case OpTyping::Light:
      return typeLight(e);
    case OpTyping::ToFloat:
      return typeFrom(e, convertsToFloat, "need Uint, Float16 or Float64", V::Float);
    case OpTyping::ToUint:
      return typeFrom(e, convertsToUint, "need Float or a sized scalar", V::Uint);
    case OpTyping::HighWord:
      return typeFrom(e, hasHighWord, "need Int64 or Uint64", V::Uint);
    case OpTyping::Convert:
      return typeConversion(e);
    case OpTyping::ConstructSized:
      return typeConstructSized(e);
    case OpTyping::Load:  // typed before its arguments (typeLoad)
      break;
  }
  return err(e, "operator '" + e.name + "' has no typing rule");
}

// {load: [var.NAME, index]}: an element of an array local.
Typing typeLoad(Expr& e, Stage stage, const LocalScope* locals) {
  Expr& array = e.args[0];
  const LocalInfo* info =
      array.kind == Expr::Kind::Local && locals ? locals->find(array.name) : nullptr;
  if (!info || info->elements == 0)
    return err(e, "operator 'load' reads an array local: {load: [var.NAME, index]}");
  array.type = info->type;
  if (auto r = checkExpr(e.args[1], stage, locals)) return r;
  if (e.args[1].type != ValueType::Uint) return badArguments(e, "need an array and a Uint index");
  e.type = info->type;
  return std::nullopt;
}

Typing typeLocal(Expr& e, const LocalScope* locals) {
  if (auto problem = locals ? locals->memberProblem(e.name) : std::nullopt)
    return err(e, "'var." + e.name + "': " + *problem);
  const LocalInfo* info = locals ? locals->find(e.name) : nullptr;
  if (!info)
    return err(e, "local 'var." + e.name +
                      "' is not declared here (let, array, repeat var, or a parameter)");
  if (info->elements)
    return err(e, "'var." + e.name + "' is an array: read an element with {load: [var." + e.name +
                      ", index]}");
  e.type = info->type;
  return std::nullopt;
}

// A ray query getter (program/builtin_table.h) where the innermost ray_query
// defines it: committed.* and query.* in any of its blocks, candidate.* in
// its candidate blocks only (after traversal a candidate is undefined,
// R-RQ-VALUES), a triangle's t, barycentrics and facing in a triangle block,
// aabb_opaque in an aabb block.
Typing typeQueryGetter(const Expr& e, const LocalScope* locals) {
  using Block = LocalScope::QueryBlock;
  const Block block = locals ? locals->queryBlock() : Block::None;
  const std::string& n = e.name;
  const Builtin b = e.builtin;
  if (block == Block::None)
    return err(e, "'" + n +
                      "' reads a ray query: only inside a ray_query's triangle, aabb or "
                      "after block");
  if (!isCandidateGetter(b)) return std::nullopt;
  if (block == Block::After)
    return err(e, "'" + n +
                      "' reads the current candidate: only in a ray_query's triangle or aabb "
                      "block (after traversal it is undefined, R-RQ-VALUES)");
  const bool triangle_only = b == kBiQCandT || b == kBiQCandBarycentrics || b == kBiQCandFrontFace;
  if (block == Block::Aabb && triangle_only)
    return err(e, "'" + n + "' is a triangle candidate's: not readable in an aabb block");
  if (block == Block::Triangle && b == kBiQCandAabbOpaque)
    return err(e, "'" + n + "' is an AABB candidate's: not readable in a triangle block");
  return std::nullopt;
}

// sphere_hit, sphere_near, sphere_far: an intersection program's own box,
// or in a ray_query's aabb block (of any other stage) the query's AABB
// candidate's (its box and object-space ray). Not in an intersection
// program's aabb block, where one function's GLSL would read either box.
std::optional<ProgramError> checkSphereOp(const Expr& e, Stage stage, const LocalScope* locals) {
  const bool aabb_block = locals && locals->queryBlock() == LocalScope::QueryBlock::Aabb;
  if (stage == Stage::Intersection && aabb_block)
    return err(e, "operator '" + e.name +
                      "' in an intersection program reads its own box: not in a ray_query's "
                      "aabb block");
  if (stage != Stage::Intersection && !aabb_block)
    return err(e, "operator '" + e.name +
                      "' reads a box: only in intersection, or in a ray_query's aabb block (its "
                      "candidate's)");
  return std::nullopt;
}

std::optional<ProgramError> checkOp(Expr& e, Stage stage, const OpInfo& op,
                                    const LocalScope* locals) {
  const std::string& name = e.name;
  const int n = static_cast<int>(e.args.size());
  if (isSphereOp(op.id)) {
    if (auto r = checkSphereOp(e, stage, locals)) return r;
  } else if (!(op.stages & stageBit(stage))) {
    return err(e, "operator '" + name + "' is not available in " + stageName(stage));
  }
  if (n < op.min_args || n > op.max_args) {
    std::string want = op.min_args == op.max_args
                           ? std::to_string(op.min_args)
                           : std::to_string(op.min_args) + ".." + std::to_string(op.max_args);
    return err(e,
               "operator '" + name + "' takes " + want + " argument(s), got " + std::to_string(n));
  }
  if (op.typing == OpTyping::Load) return typeLoad(e, stage, locals);
  for (Expr& arg : e.args)
    if (auto r = checkExpr(arg, stage, locals)) return r;
  return typeOp(e, op.typing);
}

}  // namespace

std::optional<ProgramError> checkExpr(Expr& e, Stage stage, const LocalScope* locals) {
  switch (e.kind) {
    case Expr::Kind::Local:
      return typeLocal(e, locals);
    case Expr::Kind::Constant: {
      const SpecConstant* k = locals ? locals->findConstant(e.name) : nullptr;
      if (!k) return err(e, "'const." + e.name + "' is not in pipeline.constants");
      e.type = k->type;
      return std::nullopt;
    }
    case Expr::Kind::RecordMember: {
      const RecordMember* m = locals ? locals->findRecordMember(e.name) : nullptr;
      if (!m)
        return err(e,
                   "'shader_record." + e.name + "' is not a member of pipeline.sbt.record_layout");
      e.type = m->type;
      return std::nullopt;
    }
    case Expr::Kind::Literal:
      return checkLiteral(e);
    case Expr::Kind::Builtin: {
      if (e.builtin >= kBiCount) return err(e, "unknown built-in '" + e.name + "'");
      const BuiltinInfo& b = builtins()[e.builtin];
      if (!(b.stages & stageBit(stage))) {
        const auto q = forbiddenInterface(stage, b.needs);
        if (!q || !locals || !locals->letThrough(*q, e.name, e.loc))
          return err(e, "built-in '" + e.name + "' cannot be read in " + stageName(stage));
      }
      e.type = builtinType(static_cast<Builtin>(e.builtin), e.word);
      if (isQueryBuiltin(e.builtin)) return typeQueryGetter(e, locals);
      return std::nullopt;
    }
    case Expr::Kind::Op: {
      const OpInfo* op = findOp(e.name);
      if (!op) return err(e, "unknown operator '" + e.name + "'");
      e.op = op->id;
      return checkOp(e, stage, *op, locals);
    }
  }
  return err(e, "malformed expression");
}

std::optional<ProgramError> checkExprAs(Expr& e, Stage stage, ValueType want,
                                        const std::string& what, const LocalScope* locals) {
  if (auto r = checkExpr(e, stage, locals)) return r;
  if (want == ValueType::Float && isUintLiteral(e)) e.type = ValueType::Float;
  if (takesSizedType(e, want)) {
    e.type = want;
    if (auto r = checkLiteral(e)) return r;
  }
  if (e.type != want)
    return err(e, what + ": expected " + valueTypeName(want) + ", got " + valueTypeName(e.type));
  return std::nullopt;
}

std::optional<ProgramError> checkWideLiterals(const Program& p) {
  std::optional<ProgramError> first;
  walkExpressions(p, [&](const Expr& e) {
    if (first || e.kind != Expr::Kind::Literal || !e.wide) return;
    if (const std::string why = wideLiteralProblem(e); !why.empty()) first = err(e, why);
  });
  return first;
}

Result<void> typeCheck(Expr& e, Stage stage) {
  if (const std::optional<ProgramError> r = checkExpr(e, stage)) return errorMessage(r->message);
  return {};
}

}  // namespace rayspec
