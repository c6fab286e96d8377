// The long-lived Vulkan objects of a backend (instance, device, queue) and the
// device properties the per-case code needs. Internal to harness/vulkan.
#pragma once

#include "base/result.h"

#include <vulkan/vulkan.h>

#include <memory>

#include "vulkan/debug_messenger.h"
#include "vulkan/device_functions.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {

constexpr uint64_t kDefaultWaitTimeoutNs = 240ull * 1000 * 1000 * 1000;

struct VulkanContext {
  VkInstance instance = VK_NULL_HANDLE;
  bool validation = false;
  uint32_t validation_layer_version = 0;  // its specVersion while validation is on
  std::unique_ptr<DebugCapture> capture = std::make_unique<DebugCapture>();
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;

  VkPhysicalDevice physical = VK_NULL_HANDLE;
  DeviceInfo info;
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rt_props{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
  VkPhysicalDeviceAccelerationStructurePropertiesKHR as_props{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
  VkPhysicalDeviceProperties props{};
  VkPhysicalDeviceMemoryProperties memory{};
  // rayTracingPositionFetch enabled: the device has it and no validation
  // layer older than the extension is on (vulkan/position_fetch.h).
  bool position_fetch = false;
  // pipelineLibraryGroupHandles enabled, on the same terms
  // (vulkan/library_group_handles.h): library handles are compared.
  bool library_group_handles = false;

  VkDevice device = VK_NULL_HANDLE;
  uint32_t queue_family = 0;
  VkQueue queue = VK_NULL_HANDLE;
  DeviceFunctions fn;
  // How long one submission (builds, copies, the launch) may run before it
  // is VK_TIMEOUT: past the case's own device timeout (VulkanOptions), so
  // that a slow first dispatch (lavapipe compiles shaders then) is judged by
  // the case timeout the user set, not cut short here.
  uint64_t wait_timeout_ns = kDefaultWaitTimeoutNs;
  VkPipelineCache pipeline_cache =
      VK_NULL_HANDLE;  // vulkan/pipeline_cache.h; none on a device per case
};

// instance.cpp: creates ctx.instance (+ validation layer and messenger when
// asked for and installed), or the Device error; what was made before the
// error is in ctx for destroyInstance.
Result<void> createInstance(VulkanContext& ctx, bool want_validation);
void destroyInstance(VulkanContext& ctx);
// Every physical device of the instance, in the loader's order.
Result<std::vector<VkPhysicalDevice>> physicalDevices(VkInstance instance);

// device_select.cpp
DeviceInfo describeDevice(VkPhysicalDevice physical, uint32_t index);
// Picks ctx.physical / ctx.info, or the error that says none fits.
Result<void> selectDevice(VulkanContext& ctx, const std::string& filter);

// device.cpp: creates ctx.device, ctx.queue and loads ctx.fn, or the Device
// error (a device made before it is in ctx for destroyDevice).
Result<void> createDevice(VulkanContext& ctx);
void destroyDevice(VulkanContext& ctx);

}  // namespace rayspec
