// What the GLSL of one stage needs to know while it is being written: the
// case, the plan, the stage, and what the stage's program uses.
#pragma once

#include <set>
#include <string>

#include "case/case.h"
#include "plan/plan.h"
#include "program/payload_words.h"

namespace rayspec {

// What a stage program uses, found by walking it once.
struct StageUses {
  bool trace = false;                  // a traceRayEXT (raygen: payload; else: child)
  bool ray_query = false;              // a ray_query statement (GL_EXT_ray_query)
  bool hit_object = false;             // the stage's hit object (program/hit_object.h)
  bool hit_object_record = false;      // hit_object_record_uint / _float: its shader record
  std::set<uint32_t> trace_locations;  // the payload locations its traces pass
  bool launch_ray = false;             // raygen: some trace takes a field from this launch's ray
  bool reads_child = false;            // child.* read (closest-hit, miss): zero before a trace
  bool call = false;                   // executeCallableEXT
  bool reads_callee = false;           // callee.* read: zero before a call
  std::set<uint32_t> call_locations;   // the callable data locations its calls pass
  bool light = false;                  // light: -> lights.glsl
  bool shader_record = false;          // shader_record_* or light
  bool record_members = false;         // shader_record.NAME (pipeline.sbt.record_layout)
  bool scene = false;                  // aabb_min / aabb_max / sphere_*
  bool sphere = false;                 // sphere_*
  bool query_sphere = false;           // sphere_* of a query's AABB candidate (query_sphere.glsl)
  bool hit_attribute = false;          // barycentrics read, or a report written
  bool incoming_payload = false;       // payload.* read (outside raygen) or written
  bool cull_mask = false;              // gl_CullMaskEXT read (GL_EXT_ray_cull_mask)
  bool position_fetch = false;         // vertex_position<i> read (shaders/position_fetch.glsl)
  bool query_position_fetch = false;   // a query's vertex positions read, or vertex_position<i>
                                       // of an inlined stage (shaders/query_position_fetch.glsl)
  bool counters = false;               // a count of a kept counter
  std::set<int> record_fields;         // indices (recordFields()) of fields written
};

StageUses findStageUses(const Program& program, Stage stage, const Plan& plan);

struct StageContext {
  const Case& c;
  const Plan& plan;
  Stage stage;
  std::string name;  // "raygen", "miss0", "hit1.any_hit", ...
  StageUses uses;
  uint32_t payload_location = 0;  // miss, closest-hit, any-hit: the type of their incoming payload
  uint32_t call_data_location = 0;  // callable: the type of its incoming callable data
  // A stage of a hit group with an intersection shader: the hit attribute's
  // words (pipeline.hit_attribute.words); 0 elsewhere (a plain vec2).
  uint32_t attribute_words = 0;
  // ... and its sized members (pipeline.hit_attribute.sized); none elsewhere.
  SizedMembers attribute_sized;
  // The hit attribute is the struct RsAttr (its vec2 rs_attr.bary), not a vec2.
  bool attributeStruct() const { return attribute_words || !attribute_sized.empty(); }
  // The case expects the compiler to reject this shader (expect_rejected):
  // it declares the interface its program uses even where its stage cannot
  // (program/stage_interface.h), so that the compiler sees the real misuse.
  bool rejected = false;
  // The program is emitted as a function of raygen that a ray query loop
  // calls (Pipeline::ray_query, glsl/emit_ray_query.h): built-ins are read
  // through the query, any-hit's ignore / terminate return its verdict, a
  // report calls the group's report function. `group`: its hit group.
  bool inlined = false;
  uint32_t group = 0;
  // Raygen emitted as a compute shader (Pipeline::from_compute,
  // glsl/emit_compute.h); inlined programs are emitted into it.
  bool compute = false;
  // Inlined: the level of nested queries it runs at (1: the host stage's
  // own traces), its names suffixed from level 2 on (inlined_levels.h).
  uint32_t level = 1;
  uint32_t levels = 1;  // the host's levels: a trace at the last is skipped
  // Inside a function (pipeline.functions) the program invokes: an inlined
  // any-hit's verdict goes through rs_ah_verdict (inlined_functions.h).
  bool in_function = false;
};

}  // namespace rayspec
