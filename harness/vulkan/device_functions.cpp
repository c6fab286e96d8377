#include "vulkan/device_functions.h"

#include <string>

#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

template <typename Fn>
void load(VkDevice device, const char* name, Fn* out) {
  *out = reinterpret_cast<Fn>(vkGetDeviceProcAddr(device, name));
  if (!*out) throw VulkanError(std::string("vkGetDeviceProcAddr(") + name + "): missing");
}

}  // namespace

DeviceFunctions loadDeviceFunctions(VkDevice device) {
  DeviceFunctions f;
  load(device, "vkCreateAccelerationStructureKHR", &f.createAccelerationStructure);
  load(device, "vkDestroyAccelerationStructureKHR", &f.destroyAccelerationStructure);
  load(device, "vkGetAccelerationStructureBuildSizesKHR", &f.getAccelerationStructureBuildSizes);
  load(device, "vkGetAccelerationStructureDeviceAddressKHR",
       &f.getAccelerationStructureDeviceAddress);
  load(device, "vkCmdBuildAccelerationStructuresKHR", &f.cmdBuildAccelerationStructures);
  load(device, "vkCmdCopyAccelerationStructureKHR", &f.cmdCopyAccelerationStructure);
  load(device, "vkCmdCopyAccelerationStructureToMemoryKHR",
       &f.cmdCopyAccelerationStructureToMemory);
  load(device, "vkCmdCopyMemoryToAccelerationStructureKHR",
       &f.cmdCopyMemoryToAccelerationStructure);
  load(device, "vkGetDeviceAccelerationStructureCompatibilityKHR",
       &f.getDeviceAccelerationStructureCompatibility);
  load(device, "vkCmdWriteAccelerationStructuresPropertiesKHR",
       &f.cmdWriteAccelerationStructuresProperties);
  load(device, "vkCreateRayTracingPipelinesKHR", &f.createRayTracingPipelines);
  load(device, "vkGetRayTracingShaderGroupHandlesKHR", &f.getRayTracingShaderGroupHandles);
  load(device, "vkGetRayTracingShaderGroupStackSizeKHR", &f.getRayTracingShaderGroupStackSize);
  load(device, "vkCmdSetRayTracingPipelineStackSizeKHR", &f.cmdSetRayTracingPipelineStackSize);
  load(device, "vkCmdTraceRaysKHR", &f.cmdTraceRays);
  load(device, "vkCmdTraceRaysIndirectKHR", &f.cmdTraceRaysIndirect);
  f.cmdTraceRaysIndirect2 = reinterpret_cast<PFN_vkCmdTraceRaysIndirect2KHR>(
      vkGetDeviceProcAddr(device, "vkCmdTraceRaysIndirect2KHR"));
  return f;
}

}  // namespace rayspec
