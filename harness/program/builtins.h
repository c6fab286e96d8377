// The built-in values a stage program may read, with their type and the stages
// that may read them. Both backends give each name the meaning written here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "program/program.h"

namespace rayspec {

// Bit set of stages (1u << int(Stage)).
using StageMask = unsigned;
constexpr StageMask stageBit(Stage s) {
  return 1u << static_cast<unsigned>(s);
}
constexpr StageMask kAllStages = 0x3F;

// One-letter stage bits for the built-in, operator and statement tables.
namespace stage_letters {
constexpr StageMask R = stageBit(Stage::Raygen);
constexpr StageMask M = stageBit(Stage::Miss);
constexpr StageMask C = stageBit(Stage::ClosestHit);
constexpr StageMask A = stageBit(Stage::AnyHit);
constexpr StageMask I = stageBit(Stage::Intersection);
constexpr StageMask K = stageBit(Stage::Callable);
}  // namespace stage_letters

struct BuiltinInfo {
  const char* name;
  ValueType type;
  StageMask stages;
  const char* meaning;  // one line, shown by `rayspec show` and in errors
};

// Table of all built-ins:
//   launch_id_x, launch_id_y, launch_id_z, launch_size_x, launch_size_y,
//       launch_size_z (Uint, all stages)
//   primitive_id, instance_id, instance_custom_index, geometry_index
//       (Uint; intersection, any-hit, closest-hit)
//   hit_kind (Uint; any-hit, closest-hit)
//   hit_t (Float; any-hit: candidate t; closest-hit: the hit's t)
//   hit (Uint; closest-hit 1, miss 0)
//   ray_tmin, ray_tmax (Float), incoming_ray_flags (Uint), cull_mask (Uint:
//       gl_CullMaskEXT & 0xFF, VK_KHR_ray_tracing_maintenance1; the
//       specification says the built-in holds the mask passed, OpTraceRayKHR
//       uses only its low 8 bits, and lavapipe (Mesa 25) keeps only those:
//       the upper 24 bits are not judged),
//   world_ray_origin, world_ray_direction (Vec3)
//       (intersection, any-hit, closest-hit, miss)
//   object_ray_origin, object_ray_direction (Vec3; intersection, any-hit, closest-hit)
//   barycentrics (Vec2; any-hit, closest-hit: the hit attribute; triangle
//       barycentrics (b1, b2), or what the intersection shader reported)
//   hit_position (Vec3; any-hit, closest-hit: world origin + hit_t * world direction)
//   vertex_position0, vertex_position1, vertex_position2 (Vec3; any-hit,
//       closest-hit of triangle hits: gl_HitTriangleVertexPositionsEXT[i], the
//       hit triangle's vertices in object space in the order the geometry
//       gives them, through its geometry transform; as stored by the vertex
//       format; VK_KHR_ray_tracing_position_fetch)
//   aabb_min, aabb_max (Vec3; intersection: the primitive's box, object space)
//   payload.color (Vec4), payload.value (Uint): the incoming payload in miss,
//       closest-hit and any-hit; in raygen, the payload of its last trace
//   payload.word<i> (Uint, i below kMaxPayloadWords, 0..57): word i of the incoming payload (its
//       type's pipeline.payloads words), in raygen of the last trace's payload
//   depth (Uint; miss, closest-hit, any-hit: 1 for a trace from raygen, +1 per
//       nested trace)
//   child.color (Vec4), child.value (Uint): the payload of this stage's last
//       nested trace (closest-hit, miss); child.word<i> (Uint) its word i
//   call.position, call.normal (Vec3), call.color (Vec4), call.value (Uint):
//       the incoming callable data (callable); call.word<i> (Uint) its word
//       i (its type's pipeline.callable_data words, i below kMaxCallDataWords, 0..51)
//   callee.color (Vec4), callee.value (Uint), callee.word<i> (Uint): the
//       callable data after this stage's last call (raygen, closest-hit,
//       miss, callable)
const std::vector<BuiltinInfo>& builtins();
const BuiltinInfo* findBuiltin(const std::string& name);

}  // namespace rayspec
