// The one list of the built-in values a stage program may read. Everything
// else is generated from it: the Builtin enum (kBi<Id>, below) the parser
// resolves each name to once (Expr::builtin), the table `rayspec show`
// prints and the parser checks (program/builtins.h), the GLSL each one is
// emitted as (glsl/emit_expr.cpp); the model's meaning of each is one
// exhaustive switch (model/model_builtins.cpp), which fails to build when a
// row has none.
//
// X(Id, "name", type, stages, needs, "GLSL", "ray query GLSL", "meaning"):
//   stages: the letters of program/builtins.h (R raygen, M miss, C
//     closest-hit, A any-hit, I intersection, K callable);
//   needs: what the model, the plan and the GLSL must keep, compute or
//     declare for a program that reads it (program/builtins.h BuiltinNeeds;
//     NoNeeds for none);
//   GLSL: the expression the stage reads, or nullptr where the emitter spells
//     it itself (hit by stage; the word<i> families by index, the <type>
//     families by type: their type column stands for the member's own);
//   ray query GLSL: the same value where the stage runs inlined in raygen
//     (--through ray-query, glsl/emit_ray_query.h): read through the query
//     rs_rq, $c standing for its committed flag (false in any-hit and
//     intersection, true in closest-hit); nullptr where the emitter spells
//     it (hit, ray_tmax by stage, the word<i> families).
// The ray query getters (candidate.*, committed.*, query.*) read the
// innermost enclosing ray_query statement through the GLSL macro rs_query
// (glsl/emit_query.cpp); the candidate rows and the committed rows are in the
// same order (the model counts from kBiQCandT and kBiQCommittedT).
// Rows that are indexed families stay together in this order (the model and
// the emitter count from their first row): vertex_position0..2, the
// transforms (object_to_world0..3, _3x4_0..2, then world_to_object's).
#pragma once

#include <cstdint>

// hit_t reads gl_RayTmaxEXT, not gl_HitTEXT: GLSL_EXT_ray_tracing makes
// gl_HitTEXT an alias of gl_RayTmaxEXT in any-hit and closest-hit, but glslang
// 12 gives each name its own input variable, and a stage that reads both then
// declares two RayTmaxKHR inputs (VUID-StandaloneSpirv-OpEntryPoint-09658).
// The 3x4 transforms are read through the 4x3 matrix: glslang 12 writes SPIR-V
// the validator rejects ("Matrix access is out of bounds") when a stage reads
// gl_*3x4EXT before gl_*EXT (design.md, round 4).
// The ray query getters, a list of their own so that the model's one switch
// can name them all at once (model/model_builtins.cpp).
#define RAYSPEC_QUERY_BUILTINS(X)                                                                 \
  X(QCandT, "candidate.t", Float, kAllStages, NoNeeds,                                            \
    "rayQueryGetIntersectionTEXT(rs_query, false)", nullptr, "the current candidate's t")         \
  X(QCandCustomIndex, "candidate.instance_custom_index", Uint, kAllStages, NoNeeds,               \
    "uint(rayQueryGetIntersectionInstanceCustomIndexEXT(rs_query, false))", nullptr,              \
    "the current candidate's instance custom index")                                              \
  X(QCandInstance, "candidate.instance_id", Uint, kAllStages, NoNeeds,                            \
    "uint(rayQueryGetIntersectionInstanceIdEXT(rs_query, false))", nullptr,                       \
    "the current candidate's instance id")                                                        \
  X(QCandSbtOffset, "candidate.sbt_record_offset", Uint, kAllStages, NoNeeds,                     \
    "rayQueryGetIntersectionInstanceShaderBindingTableRecordOffsetEXT(rs_query, false)", nullptr, \
    "the current candidate's instance's SBT record offset")                                       \
  X(QCandGeometry, "candidate.geometry_index", Uint, kAllStages, NoNeeds,                         \
    "uint(rayQueryGetIntersectionGeometryIndexEXT(rs_query, false))", nullptr,                    \
    "the current candidate's geometry index")                                                     \
  X(QCandPrimitive, "candidate.primitive_id", Uint, kAllStages, NoNeeds,                          \
    "uint(rayQueryGetIntersectionPrimitiveIndexEXT(rs_query, false))", nullptr,                   \
    "the current candidate's primitive index")                                                    \
  X(QCandBarycentrics, "candidate.barycentrics", Vec2, kAllStages, NoNeeds,                       \
    "rayQueryGetIntersectionBarycentricsEXT(rs_query, false)", nullptr,                           \
    "the current candidate's barycentrics (triangles)")                                           \
  X(QCandFrontFace, "candidate.front_face", Uint, kAllStages, NoNeeds,                            \
    "uint(rayQueryGetIntersectionFrontFaceEXT(rs_query, false))", nullptr,                        \
    "the current candidate's 1 front face, 0 back face (triangles)")                              \
  X(QCandObjectOrigin, "candidate.object_ray_origin", Vec3, kAllStages, NoNeeds,                  \
    "rayQueryGetIntersectionObjectRayOriginEXT(rs_query, false)", nullptr,                        \
    "the current candidate's object-space ray origin")                                            \
  X(QCandObjectDirection, "candidate.object_ray_direction", Vec3, kAllStages, NoNeeds,            \
    "rayQueryGetIntersectionObjectRayDirectionEXT(rs_query, false)", nullptr,                     \
    "the current candidate's object-space ray direction")                                         \
  X(QCandObjectToWorld0, "candidate.object_to_world0", Vec3, kAllStages, NoNeeds,                 \
    "rayQueryGetIntersectionObjectToWorldEXT(rs_query, false)[0]", nullptr,                       \
    "the current candidate's column 0 of the object-to-world matrix")                             \
  X(QCandObjectToWorld1, "candidate.object_to_world1", Vec3, kAllStages, NoNeeds,                 \
    "rayQueryGetIntersectionObjectToWorldEXT(rs_query, false)[1]", nullptr,                       \
    "the current candidate's column 1 of the object-to-world matrix")                             \
  X(QCandObjectToWorld2, "candidate.object_to_world2", Vec3, kAllStages, NoNeeds,                 \
    "rayQueryGetIntersectionObjectToWorldEXT(rs_query, false)[2]", nullptr,                       \
    "the current candidate's column 2 of the object-to-world matrix")                             \
  X(QCandObjectToWorld3, "candidate.object_to_world3", Vec3, kAllStages, NoNeeds,                 \
    "rayQueryGetIntersectionObjectToWorldEXT(rs_query, false)[3]", nullptr,                       \
    "the current candidate's column 3 of the object-to-world matrix")                             \
  X(QCandWorldToObject0, "candidate.world_to_object0", Vec3, kAllStages, NoNeeds,                 \
    "rayQueryGetIntersectionWorldToObjectEXT(rs_query, false)[0]", nullptr,                       \
    "the current candidate's column 0 of the world-to-object matrix")                             \
  X(QCandWorldToObject1, "candidate.world_to_object1", Vec3, kAllStages, NoNeeds,                 \
    "rayQueryGetIntersectionWorldToObjectEXT(rs_query, false)[1]", nullptr,                       \
    "the current candidate's column 1 of the world-to-object matrix")                             \
  X(QCandWorldToObject2, "candidate.world_to_object2", Vec3, kAllStages, NoNeeds,                 \
    "rayQueryGetIntersectionWorldToObjectEXT(rs_query, false)[2]", nullptr,                       \
    "the current candidate's column 2 of the world-to-object matrix")                             \
  X(QCandWorldToObject3, "candidate.world_to_object3", Vec3, kAllStages, NoNeeds,                 \
    "rayQueryGetIntersectionWorldToObjectEXT(rs_query, false)[3]", nullptr,                       \
    "the current candidate's column 3 of the world-to-object matrix")                             \
  X(QCandVertex0, "candidate.vertex_position0", Vec3, kAllStages, PositionFetch,                  \
    "rs_query_positions(rs_query, 0u)[0]", nullptr,                                               \
    "the current candidate triangle's first vertex in object space (position fetch)")             \
  X(QCandVertex1, "candidate.vertex_position1", Vec3, kAllStages, PositionFetch,                  \
    "rs_query_positions(rs_query, 0u)[1]", nullptr,                                               \
    "the current candidate triangle's second vertex in object space (position fetch)")            \
  X(QCandVertex2, "candidate.vertex_position2", Vec3, kAllStages, PositionFetch,                  \
    "rs_query_positions(rs_query, 0u)[2]", nullptr,                                               \
    "the current candidate triangle's third vertex in object space (position fetch)")             \
  X(QCandType, "candidate.type", Uint, kAllStages, NoNeeds,                                       \
    "uint(rayQueryGetIntersectionTypeEXT(rs_query, false))", nullptr,                             \
    "the candidate's type: 0 triangle, 1 AABB")                                                   \
  X(QCandAabbOpaque, "candidate.aabb_opaque", Uint, kAllStages, NoNeeds,                          \
    "uint(rayQueryGetIntersectionCandidateAABBOpaqueEXT(rs_query))", nullptr,                     \
    "1 if the AABB candidate is opaque (after geometry, instance and ray flags)")                 \
  X(QCommittedT, "committed.t", Float, kAllStages, NoNeeds,                                       \
    "rayQueryGetIntersectionTEXT(rs_query, true)", nullptr, "the committed intersection's t")     \
  X(QCommittedCustomIndex, "committed.instance_custom_index", Uint, kAllStages, NoNeeds,          \
    "uint(rayQueryGetIntersectionInstanceCustomIndexEXT(rs_query, true))", nullptr,               \
    "the committed intersection's instance custom index")                                         \
  X(QCommittedInstance, "committed.instance_id", Uint, kAllStages, NoNeeds,                       \
    "uint(rayQueryGetIntersectionInstanceIdEXT(rs_query, true))", nullptr,                        \
    "the committed intersection's instance id")                                                   \
  X(QCommittedSbtOffset, "committed.sbt_record_offset", Uint, kAllStages, NoNeeds,                \
    "rayQueryGetIntersectionInstanceShaderBindingTableRecordOffsetEXT(rs_query, true)", nullptr,  \
    "the committed intersection's instance's SBT record offset")                                  \
  X(QCommittedGeometry, "committed.geometry_index", Uint, kAllStages, NoNeeds,                    \
    "uint(rayQueryGetIntersectionGeometryIndexEXT(rs_query, true))", nullptr,                     \
    "the committed intersection's geometry index")                                                \
  X(QCommittedPrimitive, "committed.primitive_id", Uint, kAllStages, NoNeeds,                     \
    "uint(rayQueryGetIntersectionPrimitiveIndexEXT(rs_query, true))", nullptr,                    \
    "the committed intersection's primitive index")                                               \
  X(QCommittedBarycentrics, "committed.barycentrics", Vec2, kAllStages, NoNeeds,                  \
    "rayQueryGetIntersectionBarycentricsEXT(rs_query, true)", nullptr,                            \
    "the committed intersection's barycentrics (triangles)")                                      \
  X(QCommittedFrontFace, "committed.front_face", Uint, kAllStages, NoNeeds,                       \
    "uint(rayQueryGetIntersectionFrontFaceEXT(rs_query, true))", nullptr,                         \
    "the committed intersection's 1 front face, 0 back face (triangles)")                         \
  X(QCommittedObjectOrigin, "committed.object_ray_origin", Vec3, kAllStages, NoNeeds,             \
    "rayQueryGetIntersectionObjectRayOriginEXT(rs_query, true)", nullptr,                         \
    "the committed intersection's object-space ray origin")                                       \
  X(QCommittedObjectDirection, "committed.object_ray_direction", Vec3, kAllStages, NoNeeds,       \
    "rayQueryGetIntersectionObjectRayDirectionEXT(rs_query, true)", nullptr,                      \
    "the committed intersection's object-space ray direction")                                    \
  X(QCommittedObjectToWorld0, "committed.object_to_world0", Vec3, kAllStages, NoNeeds,            \
    "rayQueryGetIntersectionObjectToWorldEXT(rs_query, true)[0]", nullptr,                        \
    "the committed intersection's column 0 of the object-to-world matrix")                        \
  X(QCommittedObjectToWorld1, "committed.object_to_world1", Vec3, kAllStages, NoNeeds,            \
    "rayQueryGetIntersectionObjectToWorldEXT(rs_query, true)[1]", nullptr,                        \
    "the committed intersection's column 1 of the object-to-world matrix")                        \
  X(QCommittedObjectToWorld2, "committed.object_to_world2", Vec3, kAllStages, NoNeeds,            \
    "rayQueryGetIntersectionObjectToWorldEXT(rs_query, true)[2]", nullptr,                        \
    "the committed intersection's column 2 of the object-to-world matrix")                        \
  X(QCommittedObjectToWorld3, "committed.object_to_world3", Vec3, kAllStages, NoNeeds,            \
    "rayQueryGetIntersectionObjectToWorldEXT(rs_query, true)[3]", nullptr,                        \
    "the committed intersection's column 3 of the object-to-world matrix")                        \
  X(QCommittedWorldToObject0, "committed.world_to_object0", Vec3, kAllStages, NoNeeds,            \
    "rayQueryGetIntersectionWorldToObjectEXT(rs_query, true)[0]", nullptr,                        \
    "the committed intersection's column 0 of the world-to-object matrix")                        \
  X(QCommittedWorldToObject1, "committed.world_to_object1", Vec3, kAllStages, NoNeeds,            \
    "rayQueryGetIntersectionWorldToObjectEXT(rs_query, true)[1]", nullptr,                        \
    "the committed intersection's column 1 of the world-to-object matrix")                        \
  X(QCommittedWorldToObject2, "committed.world_to_object2", Vec3, kAllStages, NoNeeds,            \
    "rayQueryGetIntersectionWorldToObjectEXT(rs_query, true)[2]", nullptr,                        \
    "the committed intersection's column 2 of the world-to-object matrix")                        \
  X(QCommittedWorldToObject3, "committed.world_to_object3", Vec3, kAllStages, NoNeeds,            \
    "rayQueryGetIntersectionWorldToObjectEXT(rs_query, true)[3]", nullptr,                        \
    "the committed intersection's column 3 of the world-to-object matrix")                        \
  X(QCommittedVertex0, "committed.vertex_position0", Vec3, kAllStages, PositionFetch,             \
    "rs_query_positions(rs_query, 1u)[0]", nullptr,                                               \
    "the committed triangle's first vertex in object space (position fetch)")                     \
  X(QCommittedVertex1, "committed.vertex_position1", Vec3, kAllStages, PositionFetch,             \
    "rs_query_positions(rs_query, 1u)[1]", nullptr,                                               \
    "the committed triangle's second vertex in object space (position fetch)")                    \
  X(QCommittedVertex2, "committed.vertex_position2", Vec3, kAllStages, PositionFetch,             \
    "rs_query_positions(rs_query, 1u)[2]", nullptr,                                               \
    "the committed triangle's third vertex in object space (position fetch)")                     \
  X(QCommittedType, "committed.type", Uint, kAllStages, NoNeeds,                                  \
    "uint(rayQueryGetIntersectionTypeEXT(rs_query, true))", nullptr,                              \
    "the committed type: 0 none, 1 triangle, 2 generated")                                        \
  X(QTmin, "query.ray_tmin", Float, kAllStages, NoNeeds, "rayQueryGetRayTMinEXT(rs_query)",       \
    nullptr, "the tmin the query was initialized with")                                           \
  X(QFlags, "query.ray_flags", Uint, kAllStages, NoNeeds, "rayQueryGetRayFlagsEXT(rs_query)",     \
    nullptr, "the ray flags the query was initialized with")                                      \
  X(QWorldOrigin, "query.world_ray_origin", Vec3, kAllStages, NoNeeds,                            \
    "rayQueryGetWorldRayOriginEXT(rs_query)", nullptr,                                            \
    "the world ray origin the query was initialized with")                                        \
  X(QWorldDirection, "query.world_ray_direction", Vec3, kAllStages, NoNeeds,                      \
    "rayQueryGetWorldRayDirectionEXT(rs_query)", nullptr,                                         \
    "the world ray direction the query was initialized with")

// The hit object getters (GL_NV_shader_invocation_reorder), a list of their own
// so that the model's one switch can name them all at once
// (model/model_builtins.cpp); they read the stage's hit object, rs_hit_object.
#define RAYSPEC_HIT_OBJECT_BUILTINS(X)                                                            \
  X(HoIsHit, "hit_object.is_hit", Uint, R | C | M, HitObject,                                     \
    "uint(hitObjectIsHitNV(rs_hit_object))", nullptr,                                             \
    "1 if the hit object holds a hit, else 0 (hitObjectIsHitNV)")                                 \
  X(HoIsMiss, "hit_object.is_miss", Uint, R | C | M, HitObject,                                   \
    "uint(hitObjectIsMissNV(rs_hit_object))", nullptr,                                            \
    "1 if the hit object holds a miss, else 0 (hitObjectIsMissNV)")                               \
  X(HoIsEmpty, "hit_object.is_empty", Uint, R | C | M, HitObject,                                 \
    "uint(hitObjectIsEmptyNV(rs_hit_object))", nullptr,                                           \
    "1 if the hit object is empty, else 0 (hitObjectIsEmptyNV)")                                  \
  X(HoInstance, "hit_object.instance_id", Uint, R | C | M, HitObject,                             \
    "uint(hitObjectGetInstanceIdNV(rs_hit_object))", nullptr, "the hit's instance id")            \
  X(HoCustomIndex, "hit_object.instance_custom_index", Uint, R | C | M, HitObject,                \
    "uint(hitObjectGetInstanceCustomIndexNV(rs_hit_object))", nullptr,                            \
    "the hit's instance custom index")                                                            \
  X(HoPrimitive, "hit_object.primitive_id", Uint, R | C | M, HitObject,                           \
    "uint(hitObjectGetPrimitiveIndexNV(rs_hit_object))", nullptr, "the hit's primitive index")    \
  X(HoGeometry, "hit_object.geometry_index", Uint, R | C | M, HitObject,                          \
    "uint(hitObjectGetGeometryIndexNV(rs_hit_object))", nullptr, "the hit's geometry index")      \
  X(HoHitKind, "hit_object.hit_kind", Uint, R | C | M, HitObject,                                 \
    "hitObjectGetHitKindNV(rs_hit_object)", nullptr,                                              \
    "the hit's hit kind (gl_HitKindEXT's values)")                                                \
  X(HoT, "hit_object.t", Float, R | C | M, HitObject, "hitObjectGetRayTMaxNV(rs_hit_object)",     \
    nullptr, "the hit's t; of a miss its ray's tmax (hitObjectGetRayTMaxNV)")                     \
  X(HoTmin, "hit_object.ray_tmin", Float, R | C | M, HitObject,                                   \
    "hitObjectGetRayTMinNV(rs_hit_object)", nullptr, "the tmin of the hit object's ray")          \
  X(HoWorldOrigin, "hit_object.world_ray_origin", Vec3, R | C | M, HitObject,                     \
    "hitObjectGetWorldRayOriginNV(rs_hit_object)", nullptr,                                       \
    "the world-space origin of the hit object's ray")                                             \
  X(HoWorldDirection, "hit_object.world_ray_direction", Vec3, R | C | M, HitObject,               \
    "hitObjectGetWorldRayDirectionNV(rs_hit_object)", nullptr,                                    \
    "the world-space direction of the hit object's ray")                                          \
  X(HoObjectOrigin, "hit_object.object_ray_origin", Vec3, R | C | M, HitObject,                   \
    "hitObjectGetObjectRayOriginNV(rs_hit_object)", nullptr, "the hit's object-space ray origin") \
  X(HoObjectDirection, "hit_object.object_ray_direction", Vec3, R | C | M, HitObject,             \
    "hitObjectGetObjectRayDirectionNV(rs_hit_object)", nullptr,                                   \
    "the hit's object-space ray direction")                                                       \
  X(HoObjectToWorld0, "hit_object.object_to_world0", Vec3, R | C | M, HitObject,                  \
    "hitObjectGetObjectToWorldNV(rs_hit_object)[0]", nullptr,                                     \
    "column 0 of the hit instance's object-to-world matrix")                                      \
  X(HoObjectToWorld1, "hit_object.object_to_world1", Vec3, R | C | M, HitObject,                  \
    "hitObjectGetObjectToWorldNV(rs_hit_object)[1]", nullptr,                                     \
    "column 1 of the hit instance's object-to-world matrix")                                      \
  X(HoObjectToWorld2, "hit_object.object_to_world2", Vec3, R | C | M, HitObject,                  \
    "hitObjectGetObjectToWorldNV(rs_hit_object)[2]", nullptr,                                     \
    "column 2 of the hit instance's object-to-world matrix")                                      \
  X(HoObjectToWorld3, "hit_object.object_to_world3", Vec3, R | C | M, HitObject,                  \
    "hitObjectGetObjectToWorldNV(rs_hit_object)[3]", nullptr,                                     \
    "column 3 of the hit instance's object-to-world matrix")                                      \
  X(HoWorldToObject0, "hit_object.world_to_object0", Vec3, R | C | M, HitObject,                  \
    "hitObjectGetWorldToObjectNV(rs_hit_object)[0]", nullptr,                                     \
    "column 0 of the hit instance's world-to-object matrix")                                      \
  X(HoWorldToObject1, "hit_object.world_to_object1", Vec3, R | C | M, HitObject,                  \
    "hitObjectGetWorldToObjectNV(rs_hit_object)[1]", nullptr,                                     \
    "column 1 of the hit instance's world-to-object matrix")                                      \
  X(HoWorldToObject2, "hit_object.world_to_object2", Vec3, R | C | M, HitObject,                  \
    "hitObjectGetWorldToObjectNV(rs_hit_object)[2]", nullptr,                                     \
    "column 2 of the hit instance's world-to-object matrix")                                      \
  X(HoWorldToObject3, "hit_object.world_to_object3", Vec3, R | C | M, HitObject,                  \
    "hitObjectGetWorldToObjectNV(rs_hit_object)[3]", nullptr,                                     \
    "column 3 of the hit instance's world-to-object matrix")                                      \
  X(HoAttributes, "hit_object.attributes", Vec2, R | C | M, HitObject,                            \
    "rs_hit_object_attributes()", nullptr,                                                        \
    "the hit's attribute (hitObjectGetAttributesNV): a triangle's barycentrics, or what the "     \
    "intersection shader reported")                                                               \
  X(HoSbtIndex, "hit_object.sbt_record_index", Uint, R | C | M, HitObject,                        \
    "hitObjectGetShaderBindingTableRecordIndexNV(rs_hit_object)", nullptr,                        \
    "the SBT record the hit object runs: a hit's index in the hit region, a miss's in the miss "  \
    "region")

#define RAYSPEC_BUILTINS(X)                                                                        \
  X(LaunchX, "launch_id_x", Uint, kAllStages, NoNeeds, "RS_LAUNCH_ID.x", "RS_LAUNCH_ID.x",         \
    "x of gl_LaunchIDEXT")                                                                         \
  X(LaunchY, "launch_id_y", Uint, kAllStages, NoNeeds, "RS_LAUNCH_ID.y", "RS_LAUNCH_ID.y",         \
    "y of gl_LaunchIDEXT")                                                                         \
  X(LaunchW, "launch_size_x", Uint, kAllStages, NoNeeds, "RS_LAUNCH_SIZE.x", "RS_LAUNCH_SIZE.x",   \
    "x of gl_LaunchSizeEXT")                                                                       \
  X(LaunchH, "launch_size_y", Uint, kAllStages, NoNeeds, "RS_LAUNCH_SIZE.y", "RS_LAUNCH_SIZE.y",   \
    "y of gl_LaunchSizeEXT")                                                                       \
  X(LaunchZ, "launch_id_z", Uint, kAllStages, NoNeeds, "RS_LAUNCH_ID.z", "RS_LAUNCH_ID.z",         \
    "z of gl_LaunchIDEXT (rays.launch)")                                                           \
  X(LaunchD, "launch_size_z", Uint, kAllStages, NoNeeds, "RS_LAUNCH_SIZE.z", "RS_LAUNCH_SIZE.z",   \
    "z of gl_LaunchSizeEXT (rays.launch)")                                                         \
  X(Primitive, "primitive_id", Uint, I | A | C, NoNeeds, "uint(gl_PrimitiveID)",                   \
    "uint(rayQueryGetIntersectionPrimitiveIndexEXT(rs_rq, $c))", "gl_PrimitiveID")                 \
  X(Instance, "instance_id", Uint, I | A | C, NoNeeds, "uint(gl_InstanceID)",                      \
    "uint(rayQueryGetIntersectionInstanceIdEXT(rs_rq, $c))", "gl_InstanceID")                      \
  X(CustomIndex, "instance_custom_index", Uint, I | A | C, NoNeeds,                                \
    "uint(gl_InstanceCustomIndexEXT)",                                                             \
    "uint(rayQueryGetIntersectionInstanceCustomIndexEXT(rs_rq, $c))", "gl_InstanceCustomIndexEXT") \
  X(Geometry, "geometry_index", Uint, I | A | C, NoNeeds, "uint(gl_GeometryIndexEXT)",             \
    "uint(rayQueryGetIntersectionGeometryIndexEXT(rs_rq, $c))", "gl_GeometryIndexEXT")             \
  X(HitKind, "hit_kind", Uint, A | C, Facing | Triangles, "gl_HitKindEXT", "rs_hit_kind",          \
    "gl_HitKindEXT")                                                                               \
  X(HitT, "hit_t", Float, A | C, NoNeeds, "gl_RayTmaxEXT", "rs_hit_t",                             \
    "gl_HitTEXT: in any-hit the candidate's t, in closest-hit the hit's t")                        \
  X(Hit, "hit", Uint, C | M, NoNeeds, nullptr, nullptr, "1 in closest-hit, 0 in miss")             \
  X(Barycentrics, "barycentrics", Vec2, A | C, HitAttribute, "rs_attr", "rs_attr",                 \
    "the hit attribute: triangle barycentrics (b1, b2), or what the intersection shader reported") \
  X(AabbMin, "aabb_min", Vec3, I, BoxData, "rs_aabb_min()", "rs_aabb_min()",                       \
    "min corner of the primitive's AABB (object space)")                                           \
  X(AabbMax, "aabb_max", Vec3, I, BoxData, "rs_aabb_max()", "rs_aabb_max()",                       \
    "max corner of the primitive's AABB (object space)")                                           \
  X(ObjectOrigin, "object_ray_origin", Vec3, I | A | C, ObjectRay, "gl_ObjectRayOriginEXT",        \
    "rayQueryGetIntersectionObjectRayOriginEXT(rs_rq, $c)", "gl_ObjectRayOriginEXT")               \
  X(ObjectDirection, "object_ray_direction", Vec3, I | A | C, ObjectRay,                           \
    "gl_ObjectRayDirectionEXT", "rayQueryGetIntersectionObjectRayDirectionEXT(rs_rq, $c)",         \
    "gl_ObjectRayDirectionEXT")                                                                    \
  X(Tmin, "ray_tmin", Float, I | A | C | M, NoNeeds, "gl_RayTminEXT",                              \
    "rayQueryGetRayTMinEXT(rs_rq)", "gl_RayTminEXT")                                               \
  X(Tmax, "ray_tmax", Float, I | A | C | M, NoNeeds, "gl_RayTmaxEXT", nullptr, "gl_RayTmaxEXT")    \
  X(Flags, "incoming_ray_flags", Uint, I | A | C | M, NoNeeds, "gl_IncomingRayFlagsEXT",           \
    "rs_q_flags", "gl_IncomingRayFlagsEXT")                                                        \
  X(WorldOrigin, "world_ray_origin", Vec3, I | A | C | M, NoNeeds, "gl_WorldRayOriginEXT",         \
    "rayQueryGetWorldRayOriginEXT(rs_rq)", "gl_WorldRayOriginEXT")                                 \
  X(WorldDirection, "world_ray_direction", Vec3, I | A | C | M, NoNeeds,                           \
    "gl_WorldRayDirectionEXT", "rayQueryGetWorldRayDirectionEXT(rs_rq)",                           \
    "gl_WorldRayDirectionEXT")                                                                     \
  X(HitPosition, "hit_position", Vec3, A | C, NoNeeds,                                             \
    "(gl_WorldRayOriginEXT + gl_RayTmaxEXT * gl_WorldRayDirectionEXT)",                            \
    "(rayQueryGetWorldRayOriginEXT(rs_rq) + rs_hit_t * rayQueryGetWorldRayDirectionEXT(rs_rq))",   \
    "world ray origin + hit_t * world ray direction")                                              \
  X(PayloadColor, "payload.color", Vec4, M | C | A | R, InPayload, "payload.color",                \
    "payload.color", "color of the incoming payload; in raygen the payload of its last trace")     \
  X(PayloadValue, "payload.value", Uint, M | C | A | R, InPayload, "payload.value",                \
    "payload.value", "value of the incoming payload; in raygen the payload of its last trace")     \
  X(Depth, "depth", Uint, M | C | A, NoNeeds, "payload.depth", "payload.depth",                    \
    "trace depth: 1 for a trace from raygen, +1 per nested trace")                                 \
  X(ChildColor, "child.color", Vec4, C | M, ChildPayload, "child.color", "child.color",            \
    "color of the payload of this stage's last trace")                                             \
  X(ChildValue, "child.value", Uint, C | M, ChildPayload, "child.value", "child.value",            \
    "value of the payload of this stage's last trace")                                             \
  X(CallPosition, "call.position", Vec3, K, CallData, "call.position", "call.position",            \
    "position of the incoming callable data")                                                      \
  X(CallNormal, "call.normal", Vec3, K, CallData, "call.normal", "call.normal",                    \
    "normal of the incoming callable data")                                                        \
  X(CallColor, "call.color", Vec4, K, CallData, "call.color", "call.color",                        \
    "color of the incoming callable data")                                                         \
  X(CallValue, "call.value", Uint, K, CallData, "call.value", "call.value",                        \
    "value of the incoming callable data")                                                         \
  X(CalleeColor, "callee.color", Vec4, R | C | M | K, CalleeData, "callee.color", "callee.color",  \
    "color of the callable data after this stage's last call")                                     \
  X(CalleeValue, "callee.value", Uint, R | C | M | K, CalleeData, "callee.value", "callee.value",  \
    "value of the callable data after this stage's last call")                                     \
  X(PayloadWord, "payload.word<i>", Uint, M | C | A | R, InPayload, nullptr, nullptr,              \
    "word i (0..57) of the incoming payload, within its type's pipeline.payloads words; in "       \
    "raygen the payload of its last trace (0 beyond that trace's type)")                           \
  X(ChildWord, "child.word<i>", Uint, C | M, ChildPayload, nullptr, nullptr,                       \
    "word i of the payload of this stage's last trace (0 beyond that trace's type)")               \
  X(CullMask, "cull_mask", Uint, I | A | C | M, CullMask, "(gl_CullMaskEXT & 0xFFu)",              \
    "(rs_q_cull_mask & 0xFFu)",                                                                    \
    "gl_CullMaskEXT & 0xFF: the low 8 bits of the cull mask the trace passed, the bits every "     \
    "reading of the specification agrees on (VK_KHR_ray_tracing_maintenance1; NotSupported "       \
    "without it)")                                                                                 \
  X(Vertex0, "vertex_position0", Vec3, A | C, PositionFetch, "rs_hit_positions[0]",                \
    "rs_query_positions(rs_rq, uint($c))[0]",                                                      \
    "gl_HitTriangleVertexPositionsEXT[0]: the hit triangle's first vertex in object space, "       \
    "through the geometry transform (VK_KHR_ray_tracing_position_fetch; triangle hits only)")      \
  X(Vertex1, "vertex_position1", Vec3, A | C, PositionFetch, "rs_hit_positions[1]",                \
    "rs_query_positions(rs_rq, uint($c))[1]",                                                      \
    "gl_HitTriangleVertexPositionsEXT[1]: the hit triangle's second vertex (as vertex_position0)") \
  X(Vertex2, "vertex_position2", Vec3, A | C, PositionFetch, "rs_hit_positions[2]",                \
    "rs_query_positions(rs_rq, uint($c))[2]",                                                      \
    "gl_HitTriangleVertexPositionsEXT[2]: the hit triangle's third vertex (as vertex_position0)")  \
  X(ObjectToWorld0, "object_to_world0", Vec3, I | A | C, NoNeeds, "gl_ObjectToWorldEXT[0]",        \
    "rayQueryGetIntersectionObjectToWorldEXT(rs_rq, $c)[0]",                                       \
    "gl_ObjectToWorldEXT[0]: column 0 of the instance's object-to-world matrix (4 columns of 3; "  \
    "object_to_world1..3 the others, 3 the translation)")                                          \
  X(ObjectToWorld1, "object_to_world1", Vec3, I | A | C, NoNeeds, "gl_ObjectToWorldEXT[1]",        \
    "rayQueryGetIntersectionObjectToWorldEXT(rs_rq, $c)[1]", "gl_ObjectToWorldEXT[1]")             \
  X(ObjectToWorld2, "object_to_world2", Vec3, I | A | C, NoNeeds, "gl_ObjectToWorldEXT[2]",        \
    "rayQueryGetIntersectionObjectToWorldEXT(rs_rq, $c)[2]", "gl_ObjectToWorldEXT[2]")             \
  X(ObjectToWorld3, "object_to_world3", Vec3, I | A | C, NoNeeds, "gl_ObjectToWorldEXT[3]",        \
    "rayQueryGetIntersectionObjectToWorldEXT(rs_rq, $c)[3]", "gl_ObjectToWorldEXT[3]")             \
  X(ObjectToWorld3x4_0, "object_to_world_3x4_0", Vec4, I | A | C, NoNeeds,                         \
    "transpose(gl_ObjectToWorldEXT)[0]",                                                           \
    "transpose(rayQueryGetIntersectionObjectToWorldEXT(rs_rq, $c))[0]",                            \
    "gl_ObjectToWorld3x4EXT[0]: row 0 of the 3x4 object-to-world matrix (_1, _2 the others)")      \
  X(ObjectToWorld3x4_1, "object_to_world_3x4_1", Vec4, I | A | C, NoNeeds,                         \
    "transpose(gl_ObjectToWorldEXT)[1]",                                                           \
    "transpose(rayQueryGetIntersectionObjectToWorldEXT(rs_rq, $c))[1]",                            \
    "gl_ObjectToWorld3x4EXT[1]")                                                                   \
  X(ObjectToWorld3x4_2, "object_to_world_3x4_2", Vec4, I | A | C, NoNeeds,                         \
    "transpose(gl_ObjectToWorldEXT)[2]",                                                           \
    "transpose(rayQueryGetIntersectionObjectToWorldEXT(rs_rq, $c))[2]",                            \
    "gl_ObjectToWorld3x4EXT[2]")                                                                   \
  X(WorldToObject0, "world_to_object0", Vec3, I | A | C, NoNeeds, "gl_WorldToObjectEXT[0]",        \
    "rayQueryGetIntersectionWorldToObjectEXT(rs_rq, $c)[0]",                                       \
    "gl_WorldToObjectEXT[0]: column 0 of the inverse (world_to_object1..3 the others)")            \
  X(WorldToObject1, "world_to_object1", Vec3, I | A | C, NoNeeds, "gl_WorldToObjectEXT[1]",        \
    "rayQueryGetIntersectionWorldToObjectEXT(rs_rq, $c)[1]", "gl_WorldToObjectEXT[1]")             \
  X(WorldToObject2, "world_to_object2", Vec3, I | A | C, NoNeeds, "gl_WorldToObjectEXT[2]",        \
    "rayQueryGetIntersectionWorldToObjectEXT(rs_rq, $c)[2]", "gl_WorldToObjectEXT[2]")             \
  X(WorldToObject3, "world_to_object3", Vec3, I | A | C, NoNeeds, "gl_WorldToObjectEXT[3]",        \
    "rayQueryGetIntersectionWorldToObjectEXT(rs_rq, $c)[3]", "gl_WorldToObjectEXT[3]")             \
  X(WorldToObject3x4_0, "world_to_object_3x4_0", Vec4, I | A | C, NoNeeds,                         \
    "transpose(gl_WorldToObjectEXT)[0]",                                                           \
    "transpose(rayQueryGetIntersectionWorldToObjectEXT(rs_rq, $c))[0]",                            \
    "gl_WorldToObject3x4EXT[0]: row 0 of the 3x4 world-to-object matrix (_1, _2 the others)")      \
  X(WorldToObject3x4_1, "world_to_object_3x4_1", Vec4, I | A | C, NoNeeds,                         \
    "transpose(gl_WorldToObjectEXT)[1]",                                                           \
    "transpose(rayQueryGetIntersectionWorldToObjectEXT(rs_rq, $c))[1]",                            \
    "gl_WorldToObject3x4EXT[1]")                                                                   \
  X(WorldToObject3x4_2, "world_to_object_3x4_2", Vec4, I | A | C, NoNeeds,                         \
    "transpose(gl_WorldToObjectEXT)[2]",                                                           \
    "transpose(rayQueryGetIntersectionWorldToObjectEXT(rs_rq, $c))[2]",                            \
    "gl_WorldToObject3x4EXT[2]")                                                                   \
  X(AttributeWord, "attribute.word<i>", Uint, A | C, HitAttribute, nullptr, nullptr,               \
    "word i (0..5) of the hit attribute (pipeline.hit_attribute.words), as the intersection "      \
    "shader reported it; hit groups with an intersection shader only")                             \
  X(CallWord, "call.word<i>", Uint, K, CallData, nullptr, nullptr,                                 \
    "word i (0..51) of the incoming callable data, within its type's pipeline.callable_data "      \
    "words")                                                                                       \
  RAYSPEC_QUERY_BUILTINS(X)                                                                        \
  X(CalleeWord, "callee.word<i>", Uint, R | C | M | K, CalleeData, nullptr, nullptr,               \
    "word i of the callable data after this stage's last call (0 beyond that call's type)")        \
  X(PayloadSized, "payload.<type>", Uint, M | C | A | R, InPayload, nullptr, nullptr,              \
    "the sized member <type> (int8 .. f64vec4) of the incoming payload, of that type, where its "  \
    "pipeline.payloads[].sized lists it; in raygen the payload of its last trace (0 where that "   \
    "trace's type has none)")                                                                      \
  X(ChildSized, "child.<type>", Uint, C | M, ChildPayload, nullptr, nullptr,                       \
    "the sized member <type> of the payload of this stage's last trace (0 where its type has "     \
    "none)")                                                                                       \
  X(CallSized, "call.<type>", Uint, K, CallData, nullptr, nullptr,                                 \
    "the sized member <type> of the incoming callable data, where its "                            \
    "pipeline.callable_data[].sized lists it")                                                     \
  X(CalleeSized, "callee.<type>", Uint, R | C | M | K, CalleeData, nullptr, nullptr,               \
    "the sized member <type> of the callable data after this stage's last call (0 where that "     \
    "call's type has none)")                                                                       \
  X(AttributeSized, "attribute.<type>", Uint, A | C, HitAttribute, nullptr, nullptr,               \
    "the sized member <type> of the hit attribute (pipeline.hit_attribute.sized), as the "         \
    "intersection shader reported it; hit groups with an intersection shader only")                \
  RAYSPEC_HIT_OBJECT_BUILTINS(X)

namespace rayspec {

// Every built-in, in the order of RAYSPEC_BUILTINS: kBi<Id>. An expression
// carries the one it reads (Expr::builtin), resolved once by the parser.
enum Builtin : uint8_t {
#define RAYSPEC_BUILTIN_ID(id, ...) kBi##id,
  RAYSPEC_BUILTINS(RAYSPEC_BUILTIN_ID)
#undef RAYSPEC_BUILTIN_ID
      kBiCount,
  kBiUnknown = 0xFF
};
static_assert(kBiCount < kBiUnknown, "a Builtin is stored in a byte");

}  // namespace rayspec
