// rayspec shared GLSL: sphere_hit, sphere_near and sphere_far in a ray
// query's aabb block (harness/program/ops.h): the sphere inscribed in the
// query's AABB candidate's box, against the candidate's object-space ray, as
// rs_sphere_current() gives an intersection shader's own. The box is read
// through scene.glsl with RS_HIT_* and RS_OBJECT_RAY_* naming rs_cand_*
// (harness/glsl/emit_ray_query.cpp, emitCandidateMacros), which are given
// back after: an inlined intersection program around the query keeps its own.
// Needs scene.glsl and sphere.glsl. Model counterpart: the sphere ops of
// StageInterpreter::opOnDemand on the query's candidate view (harness/model).
RsSphere rs_cand_sphere(rayQueryEXT query) {
  const uint instance = rs_cand_instance, geometry = rs_cand_geometry,
             primitive = rs_cand_primitive;
  const vec3 origin = rs_cand_origin, direction = rs_cand_direction;
  rs_cand_instance = uint(rayQueryGetIntersectionInstanceIdEXT(query, false));
  rs_cand_geometry = uint(rayQueryGetIntersectionGeometryIndexEXT(query, false));
  rs_cand_primitive = uint(rayQueryGetIntersectionPrimitiveIndexEXT(query, false));
  rs_cand_origin = rayQueryGetIntersectionObjectRayOriginEXT(query, false);
  rs_cand_direction = rayQueryGetIntersectionObjectRayDirectionEXT(query, false);
  const RsSphere sphere = rs_sphere_current();
  rs_cand_instance = instance;
  rs_cand_geometry = geometry;
  rs_cand_primitive = primitive;
  rs_cand_origin = origin;
  rs_cand_direction = direction;
  return sphere;
}
