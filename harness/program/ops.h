// The operators of the stage vocabulary (program/op_table.h, the one list):
// name, arity, stages, typing rule, GLSL and meaning. Both backends give each
// op the meaning written there.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/result.h"
#include "program/builtins.h"
#include "program/op_table.h"
#include "program/payload_words.h"
#include "program/program.h"
#include "program/stage_interface.h"

namespace rayspec {

// How an operator's arguments are typed (program/type_check.cpp, one rule each).
enum class OpTyping : uint8_t {
  Arithmetic,       // add sub mul div: the same numeric type, or a Float with a vector
  Modulo,           // Uint % Uint
  MinMax,           // the same numeric type
  Comparison,       // the same scalar type -> Bool
  Logic,            // Bool arguments -> Bool
  Load,             // an array local and a Uint index -> the element
  Bitwise,          // Uint, Uint -> Uint
  UintToUint,       // one Uint -> Uint
  UintToFloat,      // one Uint -> Float
  UintToBool,       // one Uint -> Bool
  FloatToUint,      // one Float -> Uint
  FloatToFloat,     // one Float -> Float
  VectorOf,         // 1 (splat) or N Float scalars -> VecN
  Component,        // a vector with that component -> Float
  Dot,              // two vectors of one size -> Float
  Vec3Only,         // Vec3 arguments -> Vec3
  Length,           // a vector -> Float
  Normalize,        // a vector -> the same vector type
  FixedBool,        // no arguments -> Bool
  FixedFloat,       // no arguments -> Float
  RecordWordUint,   // a Uint literal word index 0..7 -> Uint
  RecordWordFloat,  // a Uint literal word index 0..7 -> Float
  Light,            // a Vec3 position and a Vec3 normal -> Vec4
  ToFloat,          // Uint, Float16 or Float64 -> Float
  ToUint,           // Float, a sized integer or a sized float -> Uint
  HighWord,         // Int64 or Uint64 -> Uint
  Convert,          // -> the op's sized scalar (conversionTarget)
  ConstructSized,   // the component type's scalars -> the op's sized vector (constructorTarget)
};

// One row of program/op_table.h.
struct OpInfo {
  Op id;
  const char* name;
  int min_args, max_args;
  StageMask stages;
  OpTyping typing;
  const char* glsl;  // $0..$3 the arguments, $, $& $| all of them joined; nullptr: spelled by
                     // the emitter
  const char* meaning;
};

// Ops (program/op_table.h holds each one's meaning):
//   add, sub, mul, div    numeric; both args the same type, or a Float scalar
//                         with a vector (either side). Uint div truncates; Uint
//                         div by a constant 0 (program/constant_value.h) is a
//                         case error; by a dynamic 0, undefined (the model says so).
//   mod                   Uint % Uint (by a constant 0: a case error)
//   sphere_hit, sphere_near, sphere_far (no args): intersection, or a
//       ray_query's aabb block in any other stage (program/type_check.cpp).
//       The sphere inscribed in the primitive's AABB (center = (min+max)/2,
//       radius = smallest half extent), against the object-space ray o + t d
//       (d not normalised): roots of |o + t d - c|^2 = r^2, near <= far;
//       sphere_hit = discriminant >= 0. The primitive is the intersection
//       program's own, or the query's AABB candidate (its object-space ray).
//       Computed in float with the formula in shaders/sphere.glsl
//       (shaders/query_sphere.glsl for a candidate) and its model counterpart.
//   shader_record_uint / _float: the case parser keeps i inside
//       pipeline.sbt.record_data (parse/check_record_reads.cpp).
//   light_*: the lights of shaders/lights.glsl (what `light:` computes in a callable).

// Every row, indexed by Op.
const std::vector<OpInfo>& ops();
const OpInfo* findOp(const std::string& name);
const OpInfo& opInfo(Op op);
// The op a name spells (Op::None for none).
Op opNamed(const std::string& name);
// Words indexed by a value: payload_word .. callee_word's array; nullopt for another op.
std::optional<WordArray> wordArrayOf(Op op);
// An operator expression of `op` over args, typed `type` (what a fault or a
// rewrite builds after type checking); setOp makes e another op of the same types.
Expr opExpr(Op op, std::vector<Expr> args, ValueType type, const SourceLoc& loc);
void setOp(Expr& e, Op op);
// The families of rows that stay together in program/op_table.h.
static_assert(static_cast<int>(Op::Ge) - static_cast<int>(Op::Eq) == 5 &&
                  static_cast<int>(Op::Vec4) - static_cast<int>(Op::Vec2) == 2 &&
                  static_cast<int>(Op::CompW) - static_cast<int>(Op::CompX) == 3 &&
                  static_cast<int>(Op::SphereFar) - static_cast<int>(Op::SphereHit) == 2 &&
                  static_cast<int>(Op::LightDirectional) - static_cast<int>(Op::LightPoint) == 2,
              "eq..ge, vec2..vec4, x..w, sphere_*, light_* rows together, in order");
static_assert(static_cast<int>(Op::ToFloat64) - static_cast<int>(Op::ToInt8) ==
                      static_cast<int>(ValueType::Float64) - static_cast<int>(ValueType::Int8) &&
                  static_cast<int>(Op::ToFloat64) + 1 == static_cast<int>(Op::None),
              "the conversions last, in the order of RAYSPEC_SIZED_TYPES");
constexpr bool isConversion(Op op) {  // int8 .. float64
  return op >= Op::ToInt8 && op <= Op::ToFloat64;
}
// The sized scalar a conversion makes.
constexpr ValueType conversionTarget(Op op) {
  return static_cast<ValueType>(static_cast<int>(ValueType::Int8) + static_cast<int>(op) -
                                static_cast<int>(Op::ToInt8));
}
static_assert(static_cast<int>(Op::MakeUintVec4) - static_cast<int>(Op::MakeInt8Vec2) ==
                      static_cast<int>(ValueType::UintVec4) -
                          static_cast<int>(ValueType::Int8Vec2) &&
                  static_cast<int>(Op::MakeUintVec4) + 1 == static_cast<int>(Op::ToInt8),
              "the sized vectors' constructors in the order of their ValueType rows");
constexpr bool isSizedConstructor(Op op) {  // i8vec2 .. f64vec4, uvec2 .. uvec4
  return op >= Op::MakeInt8Vec2 && op <= Op::MakeUintVec4;
}
// The sized vector a constructor ({i8vec2: ..} .. {uvec4: ..}) makes.
constexpr ValueType constructorTarget(Op op) {
  return static_cast<ValueType>(static_cast<int>(ValueType::Int8Vec2) + static_cast<int>(op) -
                                static_cast<int>(Op::MakeInt8Vec2));
}
constexpr bool isComparison(Op op) {
  return op >= Op::Eq && op <= Op::Ge;
}
constexpr bool isVectorConstructor(Op op) {
  return op >= Op::Vec2 && op <= Op::Vec4;
}
constexpr bool isSphereOp(Op op) {  // reads the object-space ray and the box
  return op >= Op::SphereHit && op <= Op::SphereFar;
}
constexpr bool isLightOp(Op op) {  // reads this stage's shader record floats
  return op >= Op::LightPoint && op <= Op::LightDirectional;
}

// Fills Expr::type for e and its arguments, or the error (its message only:
// checkExpr in check_expr.h keeps the node). `stage` decides which built-ins
// and ops are allowed.
Result<void> typeCheck(Expr& e, Stage stage);

// Checks a whole program for a stage (statement kinds allowed in the stage,
// expression types, field names); returns the first error with its location.
struct ProgramError {
  std::string message;
  SourceLoc loc;
};
std::optional<ProgramError> checkProgram(Program& p, Stage stage,
                                         const std::vector<std::string>& counters,
                                         const std::vector<std::string>& per_ray_fields,
                                         const std::vector<SpecConstant>& constants = {},
                                         const ShaderRecordLayout* record_layout = nullptr,
                                         std::vector<InterfaceUse>* interface_uses = nullptr);

}  // namespace rayspec
