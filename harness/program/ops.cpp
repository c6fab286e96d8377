// The table of operators, as documented in ops.h. Typing rules are in
// type_check.cpp.
#include "program/ops.h"

namespace rayspec {
namespace {

constexpr StageMask kIsect = stageBit(Stage::Intersection);
constexpr int kMany = 16;  // and/or take 2 or more arguments
using stage_letters::A;
using stage_letters::C;
using stage_letters::K;
using stage_letters::M;
using stage_letters::R;

}  // namespace

const std::vector<OpInfo>& ops() {
  static const std::vector<OpInfo> table = {
      {"add", 2, 2, kAllStages, "a + b (same numeric type, or Float scalar with a vector)"},
      {"sub", 2, 2, kAllStages, "a - b (same numeric type, or Float scalar with a vector)"},
      {"mul", 2, 2, kAllStages, "a * b (same numeric type, or Float scalar with a vector)"},
      {"div", 2, 2, kAllStages, "a / b (Uint division truncates)"},
      {"mod", 2, 2, kAllStages, "a % b (Uint)"},
      {"min", 2, 2, kAllStages, "smaller of a and b (same numeric type)"},
      {"max", 2, 2, kAllStages, "larger of a and b (same numeric type)"},
      {"eq", 2, 2, kAllStages, "a == b (same scalar type) -> Bool"},
      {"ne", 2, 2, kAllStages, "a != b (same scalar type) -> Bool"},
      {"lt", 2, 2, kAllStages, "a < b (same scalar type) -> Bool"},
      {"le", 2, 2, kAllStages, "a <= b (same scalar type) -> Bool"},
      {"gt", 2, 2, kAllStages, "a > b (same scalar type) -> Bool"},
      {"ge", 2, 2, kAllStages, "a >= b (same scalar type) -> Bool"},
      {"and", 2, kMany, kAllStages, "all arguments true (Bool)"},
      {"or", 2, kMany, kAllStages, "any argument true (Bool)"},
      {"not", 1, 1, kAllStages, "negation (Bool)"},
      {"load", 2, 2, kAllStages,
       "element (index % size) of an array local: {load: [var.NAME, index]}"},
      {"bit_and", 2, 2, kAllStages, "a & b (Uint)"},
      {"bit_or", 2, 2, kAllStages, "a | b (Uint)"},
      {"bit_xor", 2, 2, kAllStages, "a ^ b (Uint)"},
      {"bit_not", 1, 1, kAllStages, "~a (Uint)"},
      {"shl", 2, 2, kAllStages,
       "a << (b % 32) (Uint; GLSL leaves a shift of 32 or more undefined)"},
      {"shr", 2, 2, kAllStages, "a >> (b % 32) (Uint, logical)"},
      {"payload_word", 1, 1, M | C | A | R,
       "word (i % N) of the incoming payload (raygen: the last trace's), N its type's words"},
      {"child_word", 1, 1, C | M,
       "word (i % N) of the last nested trace's payload, N the largest payload type's words"},
      {"call_word", 1, 1, K, "word (i % N) of the incoming callable data, N its type's words"},
      {"callee_word", 1, 1, R | C | M | K,
       "word (i % N) of the last call's data, N the largest callable data type's words"},
      {"float_bits", 1, 1, kAllStages, "the bits of a Float as Uint (floatBitsToUint)"},
      {"bits_float", 1, 1, kAllStages, "a Uint's bits as Float (uintBitsToFloat)"},
      {"odd", 1, 1, kAllStages, "Uint is odd -> Bool"},
      {"even", 1, 1, kAllStages, "Uint is even -> Bool"},
      {"float", 1, 1, kAllStages, "Uint -> Float"},
      {"uint", 1, 1, kAllStages, "Float -> Uint, truncation toward zero"},
      {"round", 1, 1, kAllStages,
       "Float -> the nearest whole Float, halfway cases to even (GLSL roundEven: the same on "
       "every device)"},
      {"vec2", 1, 2, kAllStages, "Float scalars -> Vec2 (a single Float splats)"},
      {"vec3", 1, 3, kAllStages, "Float scalars -> Vec3 (a single Float splats)"},
      {"vec4", 1, 4, kAllStages, "Float scalars -> Vec4 (a single Float splats)"},
      {"x", 1, 1, kAllStages, "first component of a vector -> Float"},
      {"y", 1, 1, kAllStages, "second component of a vector -> Float"},
      {"z", 1, 1, kAllStages, "third component of a vector -> Float"},
      {"w", 1, 1, kAllStages, "fourth component of a vector -> Float"},
      {"dot", 2, 2, kAllStages, "dot product of two vectors of the same size -> Float"},
      {"cross", 2, 2, kAllStages, "cross product of two Vec3 -> Vec3"},
      {"mat3_mul", 4, 4, kAllStages,
       "mat3_mul(c0, c1, c2, v): the 3x3 matrix of columns c0 c1 c2 times Vec3 v -> Vec3"},
      {"mat3_tmul", 4, 4, kAllStages,
       "mat3_tmul(c0, c1, c2, v): the transpose of that matrix times v, (c0.v, c1.v, c2.v)"},
      {"length", 1, 1, kAllStages, "length of a vector -> Float"},
      {"normalize", 1, 1, kAllStages, "vector / its length"},
      {"sphere_hit", 0, 0, kIsect,
       "the object-space ray meets the sphere inscribed in the AABB (discriminant >= 0)"},
      {"sphere_near", 0, 0, kIsect, "near root t of the ray against the inscribed sphere"},
      {"sphere_far", 0, 0, kIsect, "far root t of the ray against the inscribed sphere"},
      {"shader_record_uint", 1, 1, kAllStages,
       "word i (Uint literal 0..7, 4 i + 4 <= pipeline.sbt.record_data) of this stage's shader "
       "record data, as Uint"},
      {"shader_record_float", 1, 1, kAllStages,
       "word i (Uint literal 0..7, 4 i + 4 <= pipeline.sbt.record_data) of this stage's shader "
       "record data, as Float"},
      {"light_point", 2, 2, kAllStages,
       "light_point(P, N): the point light of shaders/lights.glsl, parameters from this stage's "
       "record floats"},
      {"light_spot", 2, 2, kAllStages,
       "light_spot(P, N): the spot light of shaders/lights.glsl, parameters from this stage's "
       "record floats"},
      {"light_directional", 2, 2, kAllStages,
       "light_directional(P, N): the directional light of shaders/lights.glsl, parameters from "
       "this stage's record floats"},
  };
  return table;
}

const OpInfo* findOp(const std::string& name) {
  for (const OpInfo& o : ops())
    if (name == o.name) return &o;
  return nullptr;
}

}  // namespace rayspec
