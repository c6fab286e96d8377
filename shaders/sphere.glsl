// rayspec shared GLSL: the sphere inscribed in the current primitive's AABB,
// against the object-space ray o + t d (d not normalised), for the ops
// sphere_hit, sphere_near, sphere_far (harness/program/ops.h). Needs scene.glsl.
// `precise` keeps the compiler from fusing operations, so the float results
// follow the model counterpart (harness/model) operation by operation.

struct RsSphere {
  bool hit;
  float t_near;
  float t_far;
};

RsSphere rs_sphere(vec3 bmin, vec3 bmax, vec3 o, vec3 d) {
  precise vec3 c = (bmin + bmax) * 0.5;
  precise vec3 h = (bmax - bmin) * 0.5;
  precise float r = min(min(h.x, h.y), h.z);
  precise vec3 oc = o - c;
  precise float a = dot(d, d);
  precise float b = dot(oc, d);
  precise float cc = dot(oc, oc) - r * r;
  precise float disc = b * b - a * cc;
  precise float s = sqrt(max(disc, 0.0));
  RsSphere sp;
  sp.hit = disc >= 0.0;
  sp.t_near = (-b - s) / a;
  sp.t_far = (-b + s) / a;
  return sp;
}

// The sphere of the primitive this intersection shader runs for (the object
// ray is RS_OBJECT_RAY_ORIGIN / _DIRECTION where defined first, as scene.glsl).
#ifndef RS_OBJECT_RAY_ORIGIN
#define RS_OBJECT_RAY_ORIGIN gl_ObjectRayOriginEXT
#define RS_OBJECT_RAY_DIRECTION gl_ObjectRayDirectionEXT
#endif
RsSphere rs_sphere_current() {
  return rs_sphere(rs_aabb_min(), rs_aabb_max(), RS_OBJECT_RAY_ORIGIN, RS_OBJECT_RAY_DIRECTION);
}
