#include "vulkan/device_functions.h"

#include <string>

#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

// Loads one entry point; `missing` keeps the name of the first that is not there.
template <typename Fn>
void load(VkDevice device, const char* name, Fn* out, std::string& missing) {
  *out = reinterpret_cast<Fn>(vkGetDeviceProcAddr(device, name));
  if (!*out && missing.empty()) missing = name;
}

}  // namespace

Result<DeviceFunctions> loadDeviceFunctions(VkDevice device) {
  DeviceFunctions f;
  std::string missing;
  load(device, "vkCreateAccelerationStructureKHR", &f.createAccelerationStructure, missing);
  load(device, "vkDestroyAccelerationStructureKHR", &f.destroyAccelerationStructure, missing);
  load(device, "vkGetAccelerationStructureBuildSizesKHR", &f.getAccelerationStructureBuildSizes,
       missing);
  load(device, "vkGetAccelerationStructureDeviceAddressKHR",
       &f.getAccelerationStructureDeviceAddress, missing);
  load(device, "vkCmdBuildAccelerationStructuresKHR", &f.cmdBuildAccelerationStructures, missing);
  f.cmdBuildAccelerationStructuresIndirect =
      reinterpret_cast<PFN_vkCmdBuildAccelerationStructuresIndirectKHR>(
          vkGetDeviceProcAddr(device, "vkCmdBuildAccelerationStructuresIndirectKHR"));
  load(device, "vkCmdCopyAccelerationStructureKHR", &f.cmdCopyAccelerationStructure, missing);
  load(device, "vkCmdCopyAccelerationStructureToMemoryKHR", &f.cmdCopyAccelerationStructureToMemory,
       missing);
  load(device, "vkCmdCopyMemoryToAccelerationStructureKHR", &f.cmdCopyMemoryToAccelerationStructure,
       missing);
  load(device, "vkGetDeviceAccelerationStructureCompatibilityKHR",
       &f.getDeviceAccelerationStructureCompatibility, missing);
  load(device, "vkCmdWriteAccelerationStructuresPropertiesKHR",
       &f.cmdWriteAccelerationStructuresProperties, missing);
  f.writeAccelerationStructuresProperties =
      reinterpret_cast<PFN_vkWriteAccelerationStructuresPropertiesKHR>(
          vkGetDeviceProcAddr(device, "vkWriteAccelerationStructuresPropertiesKHR"));
  load(device, "vkCreateRayTracingPipelinesKHR", &f.createRayTracingPipelines, missing);
  load(device, "vkGetRayTracingShaderGroupHandlesKHR", &f.getRayTracingShaderGroupHandles, missing);
  load(device, "vkGetRayTracingShaderGroupStackSizeKHR", &f.getRayTracingShaderGroupStackSize,
       missing);
  load(device, "vkCmdSetRayTracingPipelineStackSizeKHR", &f.cmdSetRayTracingPipelineStackSize,
       missing);
  load(device, "vkCmdTraceRaysKHR", &f.cmdTraceRays, missing);
  load(device, "vkCmdTraceRaysIndirectKHR", &f.cmdTraceRaysIndirect, missing);
  f.cmdTraceRaysIndirect2 = reinterpret_cast<PFN_vkCmdTraceRaysIndirect2KHR>(
      vkGetDeviceProcAddr(device, "vkCmdTraceRaysIndirect2KHR"));
  load(device, "vkCreateDeferredOperationKHR", &f.createDeferredOperation, missing);
  load(device, "vkDestroyDeferredOperationKHR", &f.destroyDeferredOperation, missing);
  load(device, "vkGetDeferredOperationMaxConcurrencyKHR", &f.getDeferredOperationMaxConcurrency,
       missing);
  load(device, "vkGetDeferredOperationResultKHR", &f.getDeferredOperationResult, missing);
  load(device, "vkDeferredOperationJoinKHR", &f.deferredOperationJoin, missing);
  if (!missing.empty()) return deviceError("vkGetDeviceProcAddr(" + missing + "): missing");
  return f;
}

}  // namespace rayspec
