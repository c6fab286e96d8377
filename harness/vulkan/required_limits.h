// The ray tracing limits the Vulkan specification requires of every device
// that has the extension (the "Required Limits" table of the Limits chapter,
// Vulkan 1.4.360), checked against what a device reports: the one list, from
// which the check, its names and `rayspec devices --check-limits` come.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vulkan/vulkan_engine.h"

namespace rayspec {

// How a reported value must relate to the specification's: Min "at least",
// Max "at most" (alignments), Exact "equal".
enum class LimitBound { Min, Max, Exact };

// Rows: X(DeviceInfo member, "limit", bound, required value, power of two,
//        the property structure, the extension whose presence makes it apply).
// The UpdateAfterBind limits apply only where the
// descriptorBindingAccelerationStructureUpdateAfterBind feature is there
// (the table's footnote 9); the check handles those two.
// clang-format off
#define RAYSPEC_REQUIRED_LIMITS(X)                                                                 \
  X(shader_group_handle_size, "shaderGroupHandleSize", Exact, 32, false, kPipelineProperties)    \
  X(max_ray_recursion_depth, "maxRayRecursionDepth", Min, 1, false, kPipelineProperties)         \
  X(max_shader_group_stride, "maxShaderGroupStride", Min, 4096, false, kPipelineProperties)      \
  X(shader_group_base_alignment, "shaderGroupBaseAlignment", Max, 64, false, kPipelineProperties) \
  X(shader_group_handle_capture_replay_size, "shaderGroupHandleCaptureReplaySize", Max, 64, false, \
    kPipelineProperties)                                                                           \
  X(max_ray_dispatch_invocation_count, "maxRayDispatchInvocationCount", Min, 1u << 30, false,     \
    kPipelineProperties)                                                                           \
  X(shader_group_handle_alignment, "shaderGroupHandleAlignment", Max, 32, true,                   \
    kPipelineProperties)                                                                           \
  X(max_ray_hit_attribute_size, "maxRayHitAttributeSize", Min, 32, false, kPipelineProperties)   \
  X(max_geometry_count, "maxGeometryCount", Min, (1u << 24) - 1, false, kStructureProperties)    \
  X(max_instance_count, "maxInstanceCount", Min, (1u << 24) - 1, false, kStructureProperties)    \
  X(max_primitive_count, "maxPrimitiveCount", Min, (1u << 29) - 1, false, kStructureProperties)  \
  X(max_per_stage_descriptor_acceleration_structures,                                             \
    "maxPerStageDescriptorAccelerationStructures", Min, 16, false, kStructureProperties)          \
  X(max_per_stage_descriptor_update_after_bind_acceleration_structures,                           \
    "maxPerStageDescriptorUpdateAfterBindAccelerationStructures", Min, 500000, false,             \
    kStructureProperties)                                                                          \
  X(max_descriptor_set_acceleration_structures, "maxDescriptorSetAccelerationStructures", Min, 16, \
    false, kStructureProperties)                                                                   \
  X(max_descriptor_set_update_after_bind_acceleration_structures,                                 \
    "maxDescriptorSetUpdateAfterBindAccelerationStructures", Min, 500000, false,                  \
    kStructureProperties)                                                                          \
  X(min_acceleration_structure_scratch_offset_alignment,                                          \
    "minAccelerationStructureScratchOffsetAlignment", Max, 256, true, kStructureProperties)
// clang-format on

inline constexpr const char* kPipelineProperties =
    "VkPhysicalDeviceRayTracingPipelinePropertiesKHR";
inline constexpr const char* kStructureProperties =
    "VkPhysicalDeviceAccelerationStructurePropertiesKHR";

struct LimitCheck {
  std::string name;         // "maxPrimitiveCount"
  std::string structure;    // the property structure that reports it
  uint64_t value = 0;       // what the device reports
  std::string requirement;  // "at least 536870911", "at most 64, a power of two", "exactly 32"
  bool applies = true;      // false: the device lacks the extension or the feature
  bool ok = true;
  // "limits/maxPrimitiveCount": its name in a baseline and in results.
  std::string caseName() const { return "limits/" + name; }
};

// Every limit of the table, checked against what the device reported.
std::vector<LimitCheck> checkRequiredLimits(const DeviceInfo& d);

}  // namespace rayspec
