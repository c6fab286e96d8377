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

layout(set = 0, binding = RS_BINDING_SCENE, std430) readonly buffer RsScene {
  uint rs_scene[];
};

// First word of the current primitive's box.
uint rs_scene_box_word() {
  uint table = rs_scene[1u + uint(gl_InstanceID)];
  uint first = rs_scene[table + uint(gl_GeometryIndexEXT)];
  return first + 6u * uint(gl_PrimitiveID);
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
