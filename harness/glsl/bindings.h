// The descriptor bindings and buffer layouts shared by the generated GLSL and
// the Vulkan backend (set 0). The GLSL side gets these numbers as #defines
// from the generator; nothing here is retyped in shaders/.
#pragma once

#include <cstdint>
#include <vector>

#include "case/case.h"
#include "plan/plan.h"

namespace rayspec {

constexpr uint32_t kBindingTlas = 0;       // accelerationStructureEXT
constexpr uint32_t kBindingRays = 1;       // readonly buffer: uint words, kRayWords per ray
constexpr uint32_t kBindingRecords = 2;    // buffer: the device address (uint64) of the record
                                           // words, recordWords() per ray (GL_EXT_buffer_reference)
constexpr uint32_t kBindingCounters = 3;   // buffer: uint counters[plan.counters.size()]
constexpr uint32_t kBindingScene = 4;      // readonly buffer: scene data for intersection programs
constexpr uint32_t kBindingSbtTables = 5;  // readonly buffer: the SBT as tables (ray query forms)
constexpr uint32_t kBindingFirstImage = 6;  // one storage image per plan.images entry

// pipeline.layout: empty (shaders/common.glsl RS_EMPTY_LAYOUT): no set at
// all; the buffer of binding b is reached through its device address, the
// uvec2 at word pair b of the address table (the TLAS's from
// vkGetAccelerationStructureDeviceAddressKHR), and the table's own address
// is the uint specialization constants of these ids (low word, high word),
// which every shader of the pipeline is given (vulkan/address_table.h).
constexpr uint32_t kTableLowConstantId = 1000;
constexpr uint32_t kTableHighConstantId = 1001;

// Ray layout, in 32-bit words: origin xyz, tmin, direction xyz, tmax, flags,
// cull_mask, sbt_offset, sbt_stride, miss, 3 words padding.
constexpr uint32_t kRayWords = 16;
std::vector<uint32_t> packRays(const Rays& rays);

// Scene data for intersection programs (only built when plan.scene_data).
// All indices are absolute word indices into the buffer:
//   word 0       instance count N
//   word 1 + i   i = 0..N-1: word index of the geometry table of instance i's
//                BLAS; kSceneNoTable (0xFFFFFFFF) for a null or triangle BLAS
//   then one geometry table per AABB BLAS (in Scene::blases order, shared by
//   every instance of that BLAS): word g = word index of geometry g's first box
//   then the boxes, geometry after geometry: 6 float words per box
//   (min x, y, z, max x, y, z), box p of a geometry at first + 6 * p.
// So the box of (gl_InstanceID, gl_GeometryIndexEXT, gl_PrimitiveID) starts at
// scene[scene[1 + instance] + geometry] + 6 * primitive (shaders/scene.glsl).
// Assumes the TLAS holds the instances in Scene::instances order (null ones
// included), so gl_InstanceID is the position in that list.
constexpr uint32_t kSceneNoTable = 0xFFFFFFFFu;
std::vector<uint32_t> packSceneData(const Scene& scene);

// The SBT as tables, for the ray query forms (Pipeline::ray_query and
// ray_query_in_hit; only built when plan.sbt_tables). Their inlined hit and
// miss programs do not run from the SBT: the loop finds a record's hit group
// or miss program, and the programs read their record's data words, here
// (glsl/emit_ray_query.h). Tables in a buffer rather than constant arrays in
// the shader: lavapipe 25 compiled sbt/hit-index-aabbs's 2,600 constant
// words for over 10 minutes. In 32-bit words, at these offsets:
//   hit_groups   one per hit record: its hit group, kSbtNoGroup when all-zero
//   miss_groups  one per miss record: its miss program, kSbtNoGroup when
//                all-zero or naming none
//   hit_data     record_words per hit record: its data words, then zeros
//   miss_data    the same for the miss records
// Without pipeline.sbt lists, record i is group / miss program i, data zero.
constexpr uint32_t kSbtNoGroup = 0xFFFFFFFFu;
struct SbtTables {
  uint32_t hit_records = 0, miss_records = 0, record_words = 0;
  uint32_t hit_groups = 0, miss_groups = 0, hit_data = 0, miss_data = 0;  // word offsets
  std::vector<uint32_t> words;  // never empty (a buffer of one word at least)
};
SbtTables packSbtTables(const Pipeline& p);

}  // namespace rayspec
