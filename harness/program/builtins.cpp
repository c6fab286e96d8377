// The table of built-ins, as documented in builtins.h.
#include "program/builtins.h"

#include "program/payload_words.h"

namespace rayspec {
namespace {

using namespace stage_letters;

std::vector<BuiltinInfo> rayAndDataBuiltins();

// gl_ObjectToWorldEXT, gl_WorldToObjectEXT and their 3x4 forms.
std::vector<BuiltinInfo> instanceMatrixBuiltins() {
  return {
      {"object_to_world0", ValueType::Vec3, I | A | C,
       "gl_ObjectToWorldEXT[0]: column 0 of the instance's object-to-world matrix (4 columns "
       "of 3; object_to_world1..3 the others, 3 the translation)"},
      {"object_to_world1", ValueType::Vec3, I | A | C, "gl_ObjectToWorldEXT[1]"},
      {"object_to_world2", ValueType::Vec3, I | A | C, "gl_ObjectToWorldEXT[2]"},
      {"object_to_world3", ValueType::Vec3, I | A | C, "gl_ObjectToWorldEXT[3]"},
      {"world_to_object0", ValueType::Vec3, I | A | C,
       "gl_WorldToObjectEXT[0]: column 0 of the inverse (world_to_object1..3 the others)"},
      {"world_to_object1", ValueType::Vec3, I | A | C, "gl_WorldToObjectEXT[1]"},
      {"world_to_object2", ValueType::Vec3, I | A | C, "gl_WorldToObjectEXT[2]"},
      {"world_to_object3", ValueType::Vec3, I | A | C, "gl_WorldToObjectEXT[3]"},
      {"object_to_world_3x4_0", ValueType::Vec4, I | A | C,
       "gl_ObjectToWorld3x4EXT[0]: row 0 of the 3x4 object-to-world matrix (_1, _2 the others)"},
      {"object_to_world_3x4_1", ValueType::Vec4, I | A | C, "gl_ObjectToWorld3x4EXT[1]"},
      {"object_to_world_3x4_2", ValueType::Vec4, I | A | C, "gl_ObjectToWorld3x4EXT[2]"},
      {"world_to_object_3x4_0", ValueType::Vec4, I | A | C,
       "gl_WorldToObject3x4EXT[0]: row 0 of the 3x4 world-to-object matrix (_1, _2 the others)"},
      {"world_to_object_3x4_1", ValueType::Vec4, I | A | C, "gl_WorldToObject3x4EXT[1]"},
      {"world_to_object_3x4_2", ValueType::Vec4, I | A | C, "gl_WorldToObject3x4EXT[2]"},
  };
}

}  // namespace

const std::vector<BuiltinInfo>& builtins() {
  static const std::vector<BuiltinInfo> table = [] {
    std::vector<BuiltinInfo> all = rayAndDataBuiltins();
    for (const BuiltinInfo& b : instanceMatrixBuiltins()) all.push_back(b);
    return all;
  }();
  return table;
}

namespace {

// Every built-in but the instance matrices.
std::vector<BuiltinInfo> rayAndDataBuiltins() {
  return {
      {"launch_id_x", ValueType::Uint, kAllStages, "x of gl_LaunchIDEXT"},
      {"launch_id_y", ValueType::Uint, kAllStages, "y of gl_LaunchIDEXT"},
      {"launch_size_x", ValueType::Uint, kAllStages, "x of gl_LaunchSizeEXT"},
      {"launch_size_y", ValueType::Uint, kAllStages, "y of gl_LaunchSizeEXT"},
      {"launch_id_z", ValueType::Uint, kAllStages, "z of gl_LaunchIDEXT (rays.launch)"},
      {"launch_size_z", ValueType::Uint, kAllStages, "z of gl_LaunchSizeEXT (rays.launch)"},
      {"primitive_id", ValueType::Uint, I | A | C, "gl_PrimitiveID"},
      {"instance_id", ValueType::Uint, I | A | C, "gl_InstanceID"},
      {"instance_custom_index", ValueType::Uint, I | A | C, "gl_InstanceCustomIndexEXT"},
      {"geometry_index", ValueType::Uint, I | A | C, "gl_GeometryIndexEXT"},
      {"hit_kind", ValueType::Uint, A | C, "gl_HitKindEXT"},
      {"hit_t", ValueType::Float, A | C,
       "gl_HitTEXT: in any-hit the candidate's t, in closest-hit the hit's t"},
      {"hit", ValueType::Uint, C | M, "1 in closest-hit, 0 in miss"},
      {"ray_tmin", ValueType::Float, I | A | C | M, "gl_RayTminEXT"},
      {"ray_tmax", ValueType::Float, I | A | C | M, "gl_RayTmaxEXT"},
      {"incoming_ray_flags", ValueType::Uint, I | A | C | M, "gl_IncomingRayFlagsEXT"},
      {"cull_mask", ValueType::Uint, I | A | C | M,
       "gl_CullMaskEXT & 0xFF: the low 8 bits of the cull mask the trace passed, the bits "
       "every reading of the specification agrees on (VK_KHR_ray_tracing_maintenance1; "
       "NotSupported without it)"},
      {"world_ray_origin", ValueType::Vec3, I | A | C | M, "gl_WorldRayOriginEXT"},
      {"world_ray_direction", ValueType::Vec3, I | A | C | M, "gl_WorldRayDirectionEXT"},
      {"object_ray_origin", ValueType::Vec3, I | A | C, "gl_ObjectRayOriginEXT"},
      {"object_ray_direction", ValueType::Vec3, I | A | C, "gl_ObjectRayDirectionEXT"},
      {"barycentrics", ValueType::Vec2, A | C,
       "the hit attribute: triangle barycentrics (b1, b2), or what the intersection shader "
       "reported"},
      {"hit_position", ValueType::Vec3, A | C, "world ray origin + hit_t * world ray direction"},
      {"vertex_position0", ValueType::Vec3, A | C,
       "gl_HitTriangleVertexPositionsEXT[0]: the hit triangle's first vertex in object space, "
       "through the geometry transform (VK_KHR_ray_tracing_position_fetch; triangle hits only)"},
      {"vertex_position1", ValueType::Vec3, A | C,
       "gl_HitTriangleVertexPositionsEXT[1]: the hit triangle's second vertex (as "
       "vertex_position0)"},
      {"vertex_position2", ValueType::Vec3, A | C,
       "gl_HitTriangleVertexPositionsEXT[2]: the hit triangle's third vertex (as "
       "vertex_position0)"},
      {"attribute.word<i>", ValueType::Uint, A | C,
       "word i (0..5) of the hit attribute (pipeline.hit_attribute.words), as the intersection "
       "shader reported it; hit groups with an intersection shader only"},
      {"aabb_min", ValueType::Vec3, I, "min corner of the primitive's AABB (object space)"},
      {"aabb_max", ValueType::Vec3, I, "max corner of the primitive's AABB (object space)"},
      {"payload.color", ValueType::Vec4, M | C | A | R,
       "color of the incoming payload; in raygen the payload of its last trace"},
      {"payload.value", ValueType::Uint, M | C | A | R,
       "value of the incoming payload; in raygen the payload of its last trace"},
      {"payload.word<i>", ValueType::Uint, M | C | A | R,
       "word i (0..57) of the incoming payload, within its type's pipeline.payloads words; in "
       "raygen the payload of its last trace (0 beyond that trace's type)"},
      {"depth", ValueType::Uint, M | C | A,
       "trace depth: 1 for a trace from raygen, +1 per nested trace"},
      {"child.color", ValueType::Vec4, C | M, "color of the payload of this stage's last trace"},
      {"child.value", ValueType::Uint, C | M, "value of the payload of this stage's last trace"},
      {"child.word<i>", ValueType::Uint, C | M,
       "word i of the payload of this stage's last trace (0 beyond that trace's type)"},
      {"call.position", ValueType::Vec3, K, "position of the incoming callable data"},
      {"call.normal", ValueType::Vec3, K, "normal of the incoming callable data"},
      {"call.color", ValueType::Vec4, K, "color of the incoming callable data"},
      {"call.value", ValueType::Uint, K, "value of the incoming callable data"},
      {"callee.color", ValueType::Vec4, R | C | M | K,
       "color of the callable data after this stage's last call"},
      {"callee.value", ValueType::Uint, R | C | M | K,
       "value of the callable data after this stage's last call"},
      {"call.word<i>", ValueType::Uint, K,
       "word i (0..51) of the incoming callable data, within its type's pipeline.callable_data "
       "words"},
      {"callee.word<i>", ValueType::Uint, R | C | M | K,
       "word i of the callable data after this stage's last call (0 beyond that call's type)"},
  };
}

}  // namespace

const BuiltinInfo* findBuiltin(const std::string& name) {
  // payload.word3 is the table's payload.word<i>.
  if (auto w = payloadWordBuiltin(name))
    return findBuiltin(w->child ? "child.word<i>" : "payload.word<i>");
  if (attributeWordBuiltin(name)) return findBuiltin("attribute.word<i>");
  if (auto w = callWordBuiltin(name))
    return findBuiltin(w->callee ? "callee.word<i>" : "call.word<i>");
  for (const BuiltinInfo& b : builtins())
    if (name == b.name) return &b;
  return nullptr;
}

}  // namespace rayspec
