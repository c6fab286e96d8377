#include "vulkan/device_usability.h"

#include <vulkan/vulkan.h>

namespace rayspec {

DeviceUsability deviceUsability(const DeviceInfo& d) {
  if (d.api_version_number < VK_API_VERSION_1_2) return DeviceUsability::ApiBelow12;
  if (!d.ray_tracing_extension) return DeviceUsability::NoRayTracingPipelineExtension;
  if (!d.ray_tracing_pipeline) return DeviceUsability::NoRayTracingPipelineFeature;
  if (!d.acceleration_structure_extension) return DeviceUsability::NoAccelerationStructureExtension;
  if (!d.acceleration_structure) return DeviceUsability::NoAccelerationStructureFeature;
  return DeviceUsability::Usable;
}

std::string usabilityReason(DeviceUsability u, const DeviceInfo& d) {
  switch (u) {
    case DeviceUsability::Usable:
      return "usable";
    case DeviceUsability::ApiBelow12:
      return "Vulkan " + d.api_version + " is below 1.2";
    case DeviceUsability::NoRayTracingPipelineExtension:
      return "no VK_KHR_ray_tracing_pipeline";
    case DeviceUsability::NoRayTracingPipelineFeature:
      return "VK_KHR_ray_tracing_pipeline without the rayTracingPipeline feature";
    case DeviceUsability::NoAccelerationStructureExtension:
      return "no VK_KHR_acceleration_structure (with VK_KHR_deferred_host_operations)";
    case DeviceUsability::NoAccelerationStructureFeature:
      return "VK_KHR_acceleration_structure without the accelerationStructure feature";
  }
  return "unknown";
}

}  // namespace rayspec
