// The descriptor bindings and buffer layouts shared by the generated GLSL and
// the Vulkan backend (set 0). The GLSL side gets these numbers as #defines
// from the generator; nothing here is retyped in shaders/.
#pragma once

#include <cstdint>
#include <vector>

#include "case/case.h"
#include "plan/plan.h"

namespace rayspec {

constexpr uint32_t kBindingTlas = 0;      // accelerationStructureEXT
constexpr uint32_t kBindingRays = 1;      // readonly buffer: uint words, kRayWords per ray
constexpr uint32_t kBindingRecords = 2;   // buffer: the device address (uint64) of the record
                                          // words, recordWords() per ray (GL_EXT_buffer_reference)
constexpr uint32_t kBindingCounters = 3;  // buffer: uint counters[plan.counters.size()]
constexpr uint32_t kBindingScene = 4;     // readonly buffer: scene data for intersection programs
constexpr uint32_t kBindingFirstImage = 5;  // one storage image per plan.images entry

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

}  // namespace rayspec
