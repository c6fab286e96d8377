// The one list of the sized scalar types of the stage vocabulary, and of
// their vectors: the ValueType rows (program/program.h), the conversion ops
// and the vector constructors (program/op_table.h) are generated from it.
#pragma once

// clang-format off
// The sized scalars of GL_EXT_shader_explicit_arithmetic_types (a local's,
// an array element's or a parameter's type; no payload, record or record
// member holds one). Rows: Y(X, ValueType, "name", "the case's spelling",
// "GLSL", bits, SizedKind, "the #extension it needs", "the device feature",
// "its vectors' GLSL and spelling less the component count").
// int32 is core GLSL's signed int (no #extension, no device feature: both
// columns empty); its vectors are ivec2 .. ivec4. The 32-bit unsigned scalar
// is `uint` (program/program.h), once: there is no uint32 row.
// Only what is exact in each is offered: integer add, sub, mul (wrapping
// modulo 2^bits), min, max and comparisons; float16/float64 add, sub, mul,
// min, max and comparisons whose results are exact (the model names an
// inexact one a case error: rounding and denormals are the device's choice);
// conversions ({int8: x} .. {float64: x}, uint, float, high). Each has
// vectors of 2, 3 and 4 components (i8vec2 .. f64vec4: add, sub, mul, min,
// max component by component, the same exactness; x .. w read a component;
// {i8vec3: [a, b, c]} makes one, {i8vec3: a} splats).
#define RAYSPEC_SIZED_TYPES(Y, X)                                                               \
  Y(X, Int8, "Int8", "int8", "int8_t", 8, Signed,                                              \
    "GL_EXT_shader_explicit_arithmetic_types_int8", "shaderInt8 (VK_KHR_shader_float16_int8)",  \
    "i8vec")                                                                                    \
  Y(X, Uint8, "Uint8", "uint8", "uint8_t", 8, Unsigned,                                        \
    "GL_EXT_shader_explicit_arithmetic_types_int8", "shaderInt8 (VK_KHR_shader_float16_int8)",  \
    "u8vec")                                                                                    \
  Y(X, Int16, "Int16", "int16", "int16_t", 16, Signed,                                         \
    "GL_EXT_shader_explicit_arithmetic_types_int16", "shaderInt16", "i16vec")                   \
  Y(X, Uint16, "Uint16", "uint16", "uint16_t", 16, Unsigned,                                   \
    "GL_EXT_shader_explicit_arithmetic_types_int16", "shaderInt16", "u16vec")                   \
  Y(X, Int32, "Int32", "int32", "int", 32, Signed, "", "", "ivec")                              \
  Y(X, Float16, "Float16", "float16", "float16_t", 16, Floating,                               \
    "GL_EXT_shader_explicit_arithmetic_types_float16",                                          \
    "shaderFloat16 (VK_KHR_shader_float16_int8)", "f16vec")                                     \
  Y(X, Int64, "Int64", "int64", "int64_t", 64, Signed,                                         \
    "GL_EXT_shader_explicit_arithmetic_types_int64", "shaderInt64", "i64vec")                   \
  Y(X, Uint64, "Uint64", "uint64", "uint64_t", 64, Unsigned,                                   \
    "GL_EXT_shader_explicit_arithmetic_types_int64", "shaderInt64", "u64vec")                   \
  Y(X, Float64, "Float64", "float64", "float64_t", 64, Floating,                               \
    "GL_EXT_shader_explicit_arithmetic_types_float64", "shaderFloat64", "f64vec")
// uint's vectors, uvec2 .. uvec4: the sized vectors' machinery (add, sub,
// mul wrapping modulo 2^32, min, max, x .. w, {uvec3: [a, b, c]} and splat)
// with the core uint as their component; uint itself stays the one 32-bit
// unsigned scalar (program/program.h's Uint, no row of RAYSPEC_SIZED_TYPES:
// no second spelling), so this row makes vectors only. No #extension, no
// device feature.
#define RAYSPEC_UINT_VECTORS(Y, X) Y(X, Uint, "Uint", "uint", "uint", 32, Unsigned, "", "", "uvec")
// Every row that has vectors: the sized scalars', then uint's.
#define RAYSPEC_VECTOR_ROWS(Y, X) RAYSPEC_SIZED_TYPES(Y, X) RAYSPEC_UINT_VECTORS(Y, X)
#define RAYSPEC_SIZED_AS_VALUE_TYPE(X, id, name, spelling, glsl, ...) X(id, name, spelling, 1, glsl)
// A sized scalar's vectors as ValueType rows: Int8Vec2 "i8vec2" .. Int8Vec4.
#define RAYSPEC_SIZED_VECTORS_AS_VALUE_TYPES(X, id, name, spelling, glsl, bits, kind, extension, \
                                             feature, vec)                                      \
  X(id##Vec2, name "Vec2", vec "2", 2, vec "2")                                                 \
  X(id##Vec3, name "Vec3", vec "3", 3, vec "3")                                                 \
  X(id##Vec4, name "Vec4", vec "4", 4, vec "4")
// clang-format on
