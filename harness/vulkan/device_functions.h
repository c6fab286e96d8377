// Extension entry points, loaded with vkGetDeviceProcAddr (the loader does
// not export them).
#pragma once

#include <vulkan/vulkan.h>

#include "base/result.h"

namespace rayspec {

struct DeviceFunctions {
  PFN_vkCreateAccelerationStructureKHR createAccelerationStructure = nullptr;
  PFN_vkDestroyAccelerationStructureKHR destroyAccelerationStructure = nullptr;
  PFN_vkGetAccelerationStructureBuildSizesKHR getAccelerationStructureBuildSizes = nullptr;
  PFN_vkGetAccelerationStructureDeviceAddressKHR getAccelerationStructureDeviceAddress = nullptr;
  PFN_vkCmdBuildAccelerationStructuresKHR cmdBuildAccelerationStructures = nullptr;
  // Called only where accelerationStructureIndirectBuild is enabled (may be null elsewhere).
  PFN_vkCmdBuildAccelerationStructuresIndirectKHR cmdBuildAccelerationStructuresIndirect = nullptr;
  PFN_vkCmdCopyAccelerationStructureKHR cmdCopyAccelerationStructure = nullptr;
  PFN_vkCmdCopyAccelerationStructureToMemoryKHR cmdCopyAccelerationStructureToMemory = nullptr;
  PFN_vkCmdCopyMemoryToAccelerationStructureKHR cmdCopyMemoryToAccelerationStructure = nullptr;
  PFN_vkGetDeviceAccelerationStructureCompatibilityKHR getDeviceAccelerationStructureCompatibility =
      nullptr;
  PFN_vkCmdWriteAccelerationStructuresPropertiesKHR cmdWriteAccelerationStructuresProperties =
      nullptr;
  // Called only where accelerationStructureHostCommands is enabled (may be null elsewhere).
  PFN_vkWriteAccelerationStructuresPropertiesKHR writeAccelerationStructuresProperties = nullptr;
  PFN_vkCreateRayTracingPipelinesKHR createRayTracingPipelines = nullptr;
  PFN_vkGetRayTracingShaderGroupHandlesKHR getRayTracingShaderGroupHandles = nullptr;
  PFN_vkGetRayTracingShaderGroupStackSizeKHR getRayTracingShaderGroupStackSize = nullptr;
  PFN_vkCmdSetRayTracingPipelineStackSizeKHR cmdSetRayTracingPipelineStackSize = nullptr;
  PFN_vkCmdTraceRaysKHR cmdTraceRays = nullptr;
  PFN_vkCmdTraceRaysIndirectKHR cmdTraceRaysIndirect = nullptr;
  // Only where VK_KHR_ray_tracing_maintenance1 is enabled (else null).
  PFN_vkCmdTraceRaysIndirect2KHR cmdTraceRaysIndirect2 = nullptr;
  // VK_KHR_deferred_host_operations (enabled on every device: vulkan/deferred_operation.h).
  PFN_vkCreateDeferredOperationKHR createDeferredOperation = nullptr;
  PFN_vkDestroyDeferredOperationKHR destroyDeferredOperation = nullptr;
  PFN_vkGetDeferredOperationMaxConcurrencyKHR getDeferredOperationMaxConcurrency = nullptr;
  PFN_vkGetDeferredOperationResultKHR getDeferredOperationResult = nullptr;
  PFN_vkDeferredOperationJoinKHR deferredOperationJoin = nullptr;
};

// The entry points, or the Device error naming the first one the device
// does not give.
Result<DeviceFunctions> loadDeviceFunctions(VkDevice device);

}  // namespace rayspec
