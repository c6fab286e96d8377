// Whether a device can run rayspec's cases, and if not, why: Vulkan 1.2,
// VK_KHR_ray_tracing_pipeline with its rayTracingPipeline feature, and
// VK_KHR_acceleration_structure (+ deferred host operations) with its
// accelerationStructure feature.
#pragma once

#include "vulkan/vulkan_engine.h"

namespace rayspec {

enum class DeviceUsability {
  Usable,
  ApiBelow12,
  NoRayTracingPipelineExtension,
  NoRayTracingPipelineFeature,
  NoAccelerationStructureExtension,
  NoAccelerationStructureFeature,
};

DeviceUsability deviceUsability(const DeviceInfo& d);
// For people: "no VK_KHR_ray_tracing_pipeline", "Vulkan 1.1 < 1.2", ...
std::string usabilityReason(DeviceUsability u, const DeviceInfo& d);

}  // namespace rayspec
