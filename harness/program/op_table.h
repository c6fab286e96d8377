// The one list of the operators of the stage vocabulary ({op: [args]}).
// Everything else is generated from it: the Op enum and its names, the table
// `rayspec show --vocabulary` prints and the parser checks (program/ops.h),
// the typing rule each one follows (program/type_check.cpp, one exhaustive
// switch over OpTyping), the GLSL each one is emitted as (glsl/emit_expr.cpp)
// and the ids the model evaluates (model/stage_interpreter_ops.cpp, one
// exhaustive switch over Op, which fails to build when a row has none).
//
// X(Id, "name", min args, max args, stages, typing, "GLSL", "meaning"):
//   stages: the letters of program/builtins.h (R raygen, M miss, C
//     closest-hit, A any-hit, I intersection, K callable), kAllStages;
//   typing: the OpTyping rule (program/ops.h);
//   GLSL: the expression, $0..$3 standing for the arguments' GLSL and $, $&
//     $| for all of them joined by ", ", " && ", " || "; nullptr where the
//     emitter spells it (load, the word arrays, the shader record words).
// Rows that are families stay together in this order (the model and the
// emitter count from their first row): vec2..vec4, x..w, payload_word ..
// callee_word (in program/payload_words.h's WordArray order), the sized
// vectors' constructors, then the conversions to the sized scalars last (both
// generated from RAYSPEC_SIZED_TYPES).
#pragma once

#include <cstdint>

#include "base/enum_names.h"
#include "program/sized_types.h"

// clang-format off
#define RAYSPEC_OPS(X)                                                                             \
  X(Add, "add", 2, 2, kAllStages, Arithmetic, "($0 + $1)",                                         \
    "a + b (same numeric type, or Float scalar with a vector)")                                    \
  X(Sub, "sub", 2, 2, kAllStages, Arithmetic, "($0 - $1)",                                         \
    "a - b (same numeric type, or Float scalar with a vector)")                                    \
  X(Mul, "mul", 2, 2, kAllStages, Arithmetic, "($0 * $1)",                                         \
    "a * b (same numeric type, or Float scalar with a vector)")                                    \
  X(Div, "div", 2, 2, kAllStages, Arithmetic, "($0 / $1)", "a / b (Uint division truncates)")      \
  X(Mod, "mod", 2, 2, kAllStages, Modulo, "($0 % $1)", "a % b (Uint)")                             \
  X(Min, "min", 2, 2, kAllStages, MinMax, "min($0, $1)", "smaller of a and b (same numeric type)") \
  X(Max, "max", 2, 2, kAllStages, MinMax, "max($0, $1)", "larger of a and b (same numeric type)")  \
  X(Eq, "eq", 2, 2, kAllStages, Comparison, "($0 == $1)", "a == b (same scalar type) -> Bool")     \
  X(Ne, "ne", 2, 2, kAllStages, Comparison, "($0 != $1)", "a != b (same scalar type) -> Bool")     \
  X(Lt, "lt", 2, 2, kAllStages, Comparison, "($0 < $1)", "a < b (same scalar type) -> Bool")       \
  X(Le, "le", 2, 2, kAllStages, Comparison, "($0 <= $1)", "a <= b (same scalar type) -> Bool")     \
  X(Gt, "gt", 2, 2, kAllStages, Comparison, "($0 > $1)", "a > b (same scalar type) -> Bool")       \
  X(Ge, "ge", 2, 2, kAllStages, Comparison, "($0 >= $1)", "a >= b (same scalar type) -> Bool")     \
  X(And, "and", 2, kManyArgs, kAllStages, Logic, "($&)", "all arguments true (Bool)")              \
  X(Or, "or", 2, kManyArgs, kAllStages, Logic, "($|)", "any argument true (Bool)")                 \
  X(Not, "not", 1, 1, kAllStages, Logic, "(!$0)", "negation (Bool)")                               \
  X(Load, "load", 2, 2, kAllStages, Load, nullptr,                                                 \
    "element (index % size) of an array local: {load: [var.NAME, index]}")                         \
  X(BitAnd, "bit_and", 2, 2, kAllStages, Bitwise, "($0 & $1)", "a & b (Uint)")                     \
  X(BitOr, "bit_or", 2, 2, kAllStages, Bitwise, "($0 | $1)", "a | b (Uint)")                       \
  X(BitXor, "bit_xor", 2, 2, kAllStages, Bitwise, "($0 ^ $1)", "a ^ b (Uint)")                     \
  X(BitNot, "bit_not", 1, 1, kAllStages, UintToUint, "(~$0)", "~a (Uint)")                         \
  X(Shl, "shl", 2, 2, kAllStages, Bitwise, "($0 << ($1 & 31u))",                                   \
    "a << (b % 32) (Uint; GLSL leaves a shift of 32 or more undefined)")                           \
  X(Shr, "shr", 2, 2, kAllStages, Bitwise, "($0 >> ($1 & 31u))", "a >> (b % 32) (Uint, logical)")  \
  X(PayloadWord, "payload_word", 1, 1, M | C | A | R, UintToUint, nullptr,                         \
    "word (i % N) of the incoming payload (raygen: the last trace's), N its type's words")         \
  X(ChildWord, "child_word", 1, 1, C | M, UintToUint, nullptr,                                     \
    "word (i % N) of the last nested trace's payload, N the largest payload type's words")         \
  X(CallWord, "call_word", 1, 1, K, UintToUint, nullptr,                                           \
    "word (i % N) of the incoming callable data, N its type's words")                              \
  X(CalleeWord, "callee_word", 1, 1, R | C | M | K, UintToUint, nullptr,                           \
    "word (i % N) of the last call's data, N the largest callable data type's words")              \
  X(FloatBits, "float_bits", 1, 1, kAllStages, FloatToUint, "floatBitsToUint($0)",                 \
    "the bits of a Float as Uint (floatBitsToUint)")                                               \
  X(BitsFloat, "bits_float", 1, 1, kAllStages, UintToFloat, "uintBitsToFloat($0)",                 \
    "a Uint's bits as Float (uintBitsToFloat)")                                                    \
  X(Odd, "odd", 1, 1, kAllStages, UintToBool, "(($0 & 1u) != 0u)", "Uint is odd -> Bool")          \
  X(Even, "even", 1, 1, kAllStages, UintToBool, "(($0 & 1u) == 0u)", "Uint is even -> Bool")       \
  X(ToFloat, "float", 1, 1, kAllStages, ToFloat, "float($0)",                                     \
    "Uint, Float16 or Float64 -> Float (from Float64: exact values only)")                         \
  X(ToUint, "uint", 1, 1, kAllStages, ToUint, "uint($0)",                                          \
    "Float, Float16 or Float64 -> Uint, truncation toward zero; a sized integer -> Uint, its low " \
    "32 bits (an 8- or 16-bit one extended by its own signedness)")                                \
  X(RoundEven, "round", 1, 1, kAllStages, FloatToFloat, "roundEven($0)",                           \
    "Float -> the nearest whole Float, halfway cases to even (GLSL roundEven: the same on "        \
    "every device)")                                                                               \
  X(Vec2, "vec2", 1, 2, kAllStages, VectorOf, "vec2($,)",                                          \
    "Float scalars -> Vec2 (a single Float splats)")                                               \
  X(Vec3, "vec3", 1, 3, kAllStages, VectorOf, "vec3($,)",                                          \
    "Float scalars -> Vec3 (a single Float splats)")                                               \
  X(Vec4, "vec4", 1, 4, kAllStages, VectorOf, "vec4($,)",                                          \
    "Float scalars -> Vec4 (a single Float splats)")                                               \
  X(CompX, "x", 1, 1, kAllStages, Component, "$0.x", "first component of a vector -> Float")           \
  X(CompY, "y", 1, 1, kAllStages, Component, "$0.y", "second component of a vector -> Float")          \
  X(CompZ, "z", 1, 1, kAllStages, Component, "$0.z", "third component of a vector -> Float")           \
  X(CompW, "w", 1, 1, kAllStages, Component, "$0.w", "fourth component of a vector -> Float")          \
  X(Dot, "dot", 2, 2, kAllStages, Dot, "dot($0, $1)",                                              \
    "dot product of two vectors of the same size -> Float")                                        \
  X(Cross, "cross", 2, 2, kAllStages, Vec3Only, "cross($0, $1)",                                   \
    "cross product of two Vec3 -> Vec3")                                                           \
  X(Mat3Mul, "mat3_mul", 4, 4, kAllStages, Vec3Only, "(mat3($0, $1, $2) * $3)",                    \
    "mat3_mul(c0, c1, c2, v): the 3x3 matrix of columns c0 c1 c2 times Vec3 v -> Vec3")            \
  X(Mat3TMul, "mat3_tmul", 4, 4, kAllStages, Vec3Only, "(transpose(mat3($0, $1, $2)) * $3)",       \
    "mat3_tmul(c0, c1, c2, v): the transpose of that matrix times v, (c0.v, c1.v, c2.v)")          \
  X(Length, "length", 1, 1, kAllStages, Length, "length($0)", "length of a vector -> Float")        \
  X(Normalize, "normalize", 1, 1, kAllStages, Normalize, "normalize($0)", "vector / its length")   \
  X(SphereHit, "sphere_hit", 0, 0, I, FixedBool, "rs_sphere_current().hit",                        \
    "the object-space ray meets the sphere inscribed in the AABB (discriminant >= 0)")             \
  X(SphereNear, "sphere_near", 0, 0, I, FixedFloat, "rs_sphere_current().t_near",                  \
    "near root t of the ray against the inscribed sphere")                                         \
  X(SphereFar, "sphere_far", 0, 0, I, FixedFloat, "rs_sphere_current().t_far",                     \
    "far root t of the ray against the inscribed sphere")                                          \
  X(RecordUint, "shader_record_uint", 1, 1, kAllStages, RecordWordUint, nullptr,                   \
    "word i (Uint literal 0..7, 4 i + 4 <= pipeline.sbt.record_data) of this stage's shader "      \
    "record data, as Uint")                                                                        \
  X(RecordFloat, "shader_record_float", 1, 1, kAllStages, RecordWordFloat, nullptr,                \
    "word i (Uint literal 0..7, 4 i + 4 <= pipeline.sbt.record_data) of this stage's shader "      \
    "record data, as Float")                                                                       \
  X(HitObjectRecordUint, "hit_object_record_uint", 1, 1, R | C | M, RecordWordUint,              \
    "RsHitObjectRecord(hitObjectGetShaderRecordBufferHandleNV(rs_hit_object)).words[$0]",          \
    "word i (Uint literal 0..7, 4 i + 4 <= pipeline.sbt.record_data) of the shader record data "   \
    "of the record the stage's hit object holds (hitObjectGetShaderRecordBufferHandleNV read "     \
    "through a buffer reference), as Uint")                                                        \
  X(HitObjectRecordFloat, "hit_object_record_float", 1, 1, R | C | M, RecordWordFloat,           \
    "uintBitsToFloat(RsHitObjectRecord(hitObjectGetShaderRecordBufferHandleNV(rs_hit_object))"     \
    ".words[$0])",                                                                                 \
    "word i of the shader record data of the record the stage's hit object holds, as Float")      \
  X(LightPoint, "light_point", 2, 2, kAllStages, Light, "rs_light_point($0, $1)",                  \
    "light_point(P, N): the point light of shaders/lights.glsl, parameters from this stage's "     \
    "record floats")                                                                               \
  X(LightSpot, "light_spot", 2, 2, kAllStages, Light, "rs_light_spot($0, $1)",                     \
    "light_spot(P, N): the spot light of shaders/lights.glsl, parameters from this stage's "       \
    "record floats")                                                                               \
  X(LightDirectional, "light_directional", 2, 2, kAllStages, Light,                                \
    "rs_light_directional($0, $1)",                                                                \
    "light_directional(P, N): the directional light of shaders/lights.glsl, parameters from "      \
    "this stage's record floats")                                                                 \
  X(HighWord, "high", 1, 1, kAllStages, HighWord, "uint(($0) >> 32)",                              \
    "bits 32..63 of an Int64 or Uint64 -> Uint")                                                   \
  RAYSPEC_VECTOR_ROWS(RAYSPEC_CONSTRUCTOR_OPS, X)                                                  \
  RAYSPEC_SIZED_TYPES(RAYSPEC_CONVERSION_OP, X)
// {i8vec2: [a, b]} .. {f64vec4: [a, b, c, d]}, {uvec2: ..} .. {uvec4: ..}: a
// sized vector of its component type's scalars (one splats).
#define RAYSPEC_CONSTRUCTOR_OPS(X, id, name, spelling, glsl, bits, kind, extension, feature, vec) \
  X(Make##id##Vec2, vec "2", 1, 2, kAllStages, ConstructSized, vec "2($,)",                        \
    name " scalars -> " name "Vec2 (a single one splats)")                                         \
  X(Make##id##Vec3, vec "3", 1, 3, kAllStages, ConstructSized, vec "3($,)",                        \
    name " scalars -> " name "Vec3 (a single one splats)")                                         \
  X(Make##id##Vec4, vec "4", 1, 4, kAllStages, ConstructSized, vec "4($,)",                        \
    name " scalars -> " name "Vec4 (a single one splats)")
// {int8: x} .. {float64: x}: one conversion a sized scalar (program/program.h).
#define RAYSPEC_CONVERSION_OP(X, id, name, spelling, glsl, ...)                                    \
  X(To##id, spelling, 1, 1, kAllStages, Convert, glsl "($0)",                                      \
    "-> " name ": an integer from Uint or a sized integer (truncated to its bits, or extended by "  \
    "the source's signedness), a float from Uint, Float or a sized float (exact values only)")
// clang-format on

namespace rayspec {

// Every operator, in the order of RAYSPEC_OPS; None: an expression that is
// not an operator (or one built before its name was resolved).
enum class Op : uint8_t { RAYSPEC_OPS(RAYSPEC_ENUMERATOR) None };
RAYSPEC_ENUM_NAMES(Op, RAYSPEC_OPS);

}  // namespace rayspec
