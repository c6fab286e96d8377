// The plan: the effects a case really uses, derived from the case alone.
// Both backends build only what the plan names (no filter without an any-hit
// that can run, no user geometry without AABBs, no recursion machinery for a
// one-level trace, no image nobody asked for). `rayspec show CASE` prints it.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "case/case.h"

namespace rayspec {

struct Plan {
  bool triangles = false;      // some instance reaches a triangle BLAS
  bool aabbs = false;          // some instance reaches an AABB BLAS
  bool any_hit = false;        // an any-hit can run: a group has one, and
                               // some geometry can be non-opaque under the
                               // instance flags and the rays' flags
  bool intersection = false;   // an intersection shader can run (AABBs present)
  bool closest_hit = false;    // some group has a closest-hit
  bool miss = false;           // some miss shader exists
  bool callables = false;      // some stage calls a callable
  bool nested_trace = false;   // a closest-hit or miss traces (recursion)
  uint32_t trace_depth = 1;    // deepest trace nesting the programs can reach
  bool facing_culls = false;   // cull_back/front_facing used, or flip/cull-disable instance flags
  bool masks = false;          // an instance mask or a cull mask is not 0xFF
  bool opacity_flags = false;  // opaque/no_opaque/cull_opaque/cull_no_opaque or force_* flags
  bool scene_data = false;     // a program reads the AABBs (aabb_*, sphere_*: intersection's own,
                               // a ray_query's AABB candidate's)
  bool cull_mask_builtin = false;   // a stage reads cull_mask (gl_CullMaskEXT: needs
                                    // VK_KHR_ray_tracing_maintenance1)
  bool ray_queries = false;         // a stage runs a ray_query statement (VK_KHR_ray_query)
  bool hit_objects = false;         // a stage uses a hit object (program/hit_object.h:
                                    // VK_NV_ray_tracing_invocation_reorder)
  bool dynamic_tlas_index = false;  // a trace or ray query names its top level by an
                                    // expression (rs_tlas[nonuniformEXT(i)]: descriptor
                                    // indexing)
  bool position_fetch = false;      // a stage reads vertex_position<i> or a ray query's
                                    // (gl_HitTriangleVertexPositionsEXT: needs
                                    // VK_KHR_ray_tracing_position_fetch, and
                                    // every structure built with ALLOW_DATA_ACCESS)
  // The sized scalars a stage computes with (program/sized_types.h), bit
  // 1 << ValueType: their #extension lines, the device features they need.
  uint32_t sized_types = 0;
  // Whether t, or a sized vector's component type, is among them.
  bool usesSized(ValueType t) const {
    return sized_types >> static_cast<int>(sizedComponent(t)) & 1u;
  }
  // Each distinct member list of the struct locals (Stmt::Kind::Struct) of
  // every stage, in the order met: one GLSL struct type each.
  std::vector<std::vector<std::pair<std::string, ValueType>>> struct_types;
  bool shader_record_data = false;         // some SBT record carries data
  bool zero_records = false;               // some SBT record is all zero
  bool sbt_tables = false;                 // the SBT as tables in a buffer: traced by ray
                                           // queries (Pipeline::ray_query, ray_query_in_hit)
  std::vector<std::string> counters;       // counters kept
  std::vector<std::string> record_fields;  // per-ray fields kept (recordable ones)
  bool records = false;                    // a per-ray record buffer is needed
  // The record words bound as the storage buffer of RS_BINDING_RECORDS
  // itself, not reached through a device address (shaders/common.glsl
  // RS_RECORDS_BOUND): never derived; the Amber export sets it, since an
  // Amber script cannot hand a shader a buffer's address.
  bool records_bound = false;
  std::vector<ImageOutput> images;  // images kept

  // One line per effect, for `rayspec show`.
  std::vector<std::string> describe() const;
};

Plan derivePlan(const Case& c);

struct RecordField;
// The record fields a comparison judges per ray: the plan's own, then the
// automatic ones that do not depend on the traversal (results/record_layout.h).
std::vector<const RecordField*> comparedRecordFields(const Plan& plan);

// The plan with every effect switched on: every flag of Plan set, every
// recordable field kept and shown as an image (named after it), the case's
// counters. What a case would cost without the plan (bench/plan_saving.cpp).
Plan everyEffectPlan(const Case& c);

}  // namespace rayspec
