// rayspec shared GLSL: the scene data buffer read by intersection programs
// (aabb_min, aabb_max, sphere_*). Layout, written by packSceneData
// (harness/glsl/bindings.h), all indices are absolute word indices:
//   word 0                 instance count N
//   word 1 + i             geometry table of instance i's BLAS
//                          (0xFFFFFFFF: null or triangle BLAS)
//   table[g]               first word of geometry g's boxes
//   box p of a geometry    6 float words: min xyz, max xyz
// Assumes gl_InstanceID is the instance's position in the case's instance list.
// Model counterpart: the model reads the same boxes from the Case.
// The primitive is the current one's (gl_*), or what RS_HIT_INSTANCE,
// RS_HIT_GEOMETRY and RS_HIT_PRIMITIVE name where they are defined first (a
// ray query's candidate: harness/glsl/emit_ray_query.cpp).
#ifndef RS_HIT_INSTANCE
#define RS_HIT_INSTANCE uint(gl_InstanceID)
#define RS_HIT_GEOMETRY uint(gl_GeometryIndexEXT)
#define RS_HIT_PRIMITIVE uint(gl_PrimitiveID)
#endif

#ifdef RS_EMPTY_LAYOUT
#define rs_scene RS_BOUND_WORDS(RS_BINDING_SCENE)
#else
layout(set = 0, binding = RS_BINDING_SCENE, std430) readonly buffer RsScene {
  uint rs_scene[];
};
#endif

// First word of the current primitive's box.
uint rs_scene_box_word() {
  uint table = rs_scene[1u + RS_HIT_INSTANCE];
  uint first = rs_scene[table + RS_HIT_GEOMETRY];
  return first + 6u * RS_HIT_PRIMITIVE;
}

vec3 rs_aabb_min() {
  uint w = rs_scene_box_word();
  return vec3(uintBitsToFloat(rs_scene[w + 0u]), uintBitsToFloat(rs_scene[w + 1u]),
              uintBitsToFloat(rs_scene[w + 2u]));
}

vec3 rs_aabb_max() {
  uint w = rs_scene_box_word();
  return vec3(uintBitsToFloat(rs_scene[w + 3u]), uintBitsToFloat(rs_scene[w + 4u]),
              uintBitsToFloat(rs_scene[w + 5u]));
}
