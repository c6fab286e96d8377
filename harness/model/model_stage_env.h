// What a stage program sees: the payload and callable data it reads and
// writes, the ray of its trace, the hit or candidate (HitView) and its
// frame (StageEnv), and how a statement ends (Flow).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "case/case.h"
#include "model/model_program.h"

namespace rayspec {

struct Payload {
  std::array<float, 4> color{};
  uint32_t value = 0;
  uint32_t depth = 0;
  uint32_t location = 0;  // the trace's payload location (its type: Pipeline::payload_words)
  std::array<uint32_t, kMaxPayloadWords> words{};
  SizedSlots sized;  // its type's sized members (Pipeline::payload_sized)
};

struct CallData {
  std::array<float, 4> color{};
  std::array<float, 3> position{}, normal{};
  uint32_t value = 0;
  uint32_t location = 0;  // the call's data location (its type: Pipeline::call_data_words)
  std::array<uint32_t, kMaxCallDataWords> words{};
  SizedSlots sized;  // its type's sized members (Pipeline::call_data_sized)
};

struct TraceRay {
  Vec3 origin{}, direction{};
  float tmin = 0, tmax = 0;
  uint32_t flags = 0, cull_mask = kVisibilityMask, sbt_offset = 0, sbt_stride = 1, miss = 0;
  uint32_t tlas = 0;  // the top level traversed
};

// The trace of a launch's own ray (`trace: {}` in raygen).
inline TraceRay launchRay(const Ray& base) {
  TraceRay r;
  r.origin = base.origin;
  r.direction = base.direction;
  r.tmin = base.tmin;
  r.tmax = base.tmax;
  r.flags = base.flags;
  r.cull_mask = base.cull_mask;
  r.sbt_offset = base.sbt_offset;
  r.sbt_stride = base.sbt_stride;
  r.miss = base.miss;
  return r;
}

// Built-ins of a hit or candidate.
struct HitView {
  uint32_t primitive = 0, instance = 0, custom_index = 0, geometry = 0, hit_kind = 0;
  float t = 0, b1 = 0, b2 = 0;
  Vec3 object_origin{}, object_direction{};
  Vec3 aabb_min{}, aabb_max{};
  // A triangle hit's vertices in object space (geometry transform applied):
  // the vertex_position<i> built-ins; nullptr for a box.
  const std::array<Vec3, 3>* vertices = nullptr;
  // The words a report gave the hit attribute (attribute.word<i>).
  std::array<uint32_t, kMaxAttributeWords> words{};
  SizedSlots sized;  // the sized members a report gave it (attribute.int8 ..)
};

// A stage's hit object (GL_NV_shader_invocation_reorder): empty, the
// committed hit of a trace into it (hitObjectTraceRayNV: its any-hit and
// intersection programs ran, closest-hit and miss did not) or its miss, or a
// miss recorded by hand; with the ray and SBT record executing it runs
// (ModelTracer::executeHitObject).
struct HitObjectState {
  enum class Kind : uint8_t { Empty, Hit, Miss };
  Kind kind = Kind::Empty;
  TraceRay ray;            // the ray traced or recorded (a miss: its miss index in ray.miss)
  uint32_t flags = 0;      // the ray flags traversal resolved (the pipeline's skip flags added)
  uint32_t depth = 0;      // the trace's depth, which the executed shader runs at
  uint32_t sbt_index = 0;  // the record executing it runs: a hit's in the hit region, a miss's
  HitView hit;             // a hit's built-ins (its object-space ray always computed)
  // The data of the record sbt_index names (hitObjectGetShaderRecordBufferHandleNV);
  // null where it lies beyond its region, or the hit object is empty.
  const std::vector<uint32_t>* record_data = nullptr;
};

struct Traversal;
struct QueryRun;

struct StageEnv {
  Stage stage = Stage::Raygen;
  const std::vector<uint32_t>* record_data = nullptr;
  Payload* payload = nullptr;  // incoming payload, or raygen's last trace payload
  Payload child;               // last nested trace (closest-hit, miss)
  CallData* call = nullptr;    // incoming callable data
  CallData callee;             // after this stage's last call
  const TraceRay* ray = nullptr;
  const HitView* hit = nullptr;
  float tmax_view = 0;
  uint32_t depth = 0;
  Traversal* traversal = nullptr;        // intersection (report) and any-hit
  std::vector<Val> locals;               // the frame's local variables (program/locals.h slots)
  QueryRun* query = nullptr;             // the innermost ray_query running (model/query_run.h)
  HitObjectState* hit_object = nullptr;  // raygen, closest-hit, miss: the stage's hit object
};

// How a statement ends: go on, ignore / terminate (any-hit), or leave a
// repeat (Break), an iteration (Next) or a function (Return).
enum class Flow { Continue, Ignore, Terminate, Break, Next, Return };

}  // namespace rayspec
