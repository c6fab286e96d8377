// The operators of the stage vocabulary: name, arity and typing rule. Both
// backends give each op the meaning written here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/result.h"
#include "program/builtins.h"
#include "program/program.h"
#include "program/stage_interface.h"

namespace rayspec {

struct OpInfo {
  const char* name;
  int min_args, max_args;
  StageMask stages;
  const char* meaning;
};

// Ops:
//   add, sub, mul, div    numeric; both args the same type, or a Float scalar
//                         with a vector (either side). Uint div truncates; Uint
//                         div by a constant 0 (program/constant_value.h) is a
//                         case error; by a dynamic 0, undefined (the model says so).
//   mod                   Uint % Uint (by a constant 0: a case error)
//   min, max              same numeric type
//   eq, ne, lt, le, gt, ge -> Bool; args the same scalar type
//   and, or (2+ Bool args), not (1 Bool)
//   bit_and, bit_or, bit_xor (Uint, Uint -> Uint), bit_not (Uint -> Uint)
//   shl, shr              Uint, Uint -> Uint: a shifted by b % 32 (logical)
//   float_bits (Float -> Uint: its bits), bits_float (Uint -> Float: as bits)
//   odd, even             Uint -> Bool
//   float (Uint -> Float), uint (Float -> Uint, truncation toward zero)
//   vec2, vec3, vec4      Float scalars -> vector (a single Float splats)
//   x, y, z, w            component of a vector -> Float
//   dot (2 same vectors -> Float), cross (2 Vec3 -> Vec3), length (vector -> Float),
//   mat3_mul, mat3_tmul (4 Vec3: columns c0 c1 c2 of a 3x3 matrix and v ->
//       Vec3): the matrix times v, and its transpose times v
//   normalize (vector -> same)
//   sphere_hit (no args -> Bool), sphere_near, sphere_far (no args -> Float):
//       intersection only. The sphere inscribed in the primitive's AABB
//       (center = (min+max)/2, radius = smallest half extent), against the
//       object-space ray o + t d (d not normalised): roots of
//       |o + t d - c|^2 = r^2, near <= far; sphere_hit = discriminant >= 0.
//       Computed in float with the formula in shaders/sphere.glsl and its
//       model counterpart.
//   shader_record_uint (1 Uint literal i in 0..7 -> Uint),
//   shader_record_float (same -> Float): word i of this stage's own shader
//       record data (raygen, miss, hit groups, callables); the case parser
//       keeps i inside pipeline.sbt.record_data (case/check_record_reads.cpp).
//   light_point, light_spot, light_directional (P Vec3, N Vec3 -> Vec4): the
//       lights of shaders/lights.glsl at P with normal N, parameters from this
//       stage's own shader record floats (what `light:` computes in a callable).
const std::vector<OpInfo>& ops();
const OpInfo* findOp(const std::string& name);

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
