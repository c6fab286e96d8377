// Logical device: one compute-capable queue, the ray tracing extensions and
// the features listed in vulkan_engine.h.
#include <vector>

#include "vulkan/case_support.h"
#include "vulkan/context.h"
#include "vulkan/library_group_handles.h"
#include "vulkan/position_fetch.h"
#include "vulkan/vk_check.h"

namespace rayspec {

namespace {

// Whether a feature newer than some validation layers may be enabled:
// validationLayerKnows (vulkan/case_support.h). An older layer reports the
// feature structure and the SPIR-V that uses it as errors (Debian 12's is
// 1.3.239).
bool layerKnows(const VulkanContext& ctx, uint32_t since) {
  return validationLayerKnows(ctx.validation ? ctx.validation_layer_version : 0, since);
}

template <typename Feature>
void chainFeature(VkPhysicalDeviceFeatures2& on, Feature& feature) {
  feature.p_next = on.pNext;
  on.pNext = &feature;
}

// Position fetch (1.3.249) and library group handles (1.3.240), where the
// device has them and the layer knows them.
void enableNewerFeatures(VulkanContext& ctx, VkPhysicalDeviceFeatures2& on,
                         PositionFetchFeatures& position_fetch,
                         LibraryGroupHandlesFeatures& group_handles) {
  ctx.position_fetch = ctx.info.position_fetch && layerKnows(ctx, kPositionFetchHeaderVersion);
  if (ctx.position_fetch) {
    position_fetch.ray_tracing_position_fetch = VK_TRUE;
    chainFeature(on, position_fetch);
  }
  ctx.library_group_handles =
      ctx.info.library_group_handles && layerKnows(ctx, kLibraryGroupHandlesHeaderVersion);
  if (ctx.library_group_handles) {
    group_handles.pipeline_library_group_handles = VK_TRUE;
    chainFeature(on, group_handles);
  }
}

// Hit objects and reordering (VK_NV_ray_tracing_invocation_reorder) where
// the device has them.
void enableInvocationReorder(const VulkanContext& ctx, VkPhysicalDeviceFeatures2& on,
                             VkPhysicalDeviceRayTracingInvocationReorderFeaturesNV& reorder) {
  if (!ctx.info.invocation_reorder) return;
  reorder.rayTracingInvocationReorder = VK_TRUE;
  reorder.pNext = on.pNext;
  on.pNext = &reorder;
}

// Ray queries (Pipeline::ray_query) where the device has them
// (describeDevice found the extension and its feature).
void enableRayQuery(const VulkanContext& ctx, VkPhysicalDeviceFeatures2& on,
                    VkPhysicalDeviceRayQueryFeaturesKHR& ray_query) {
  if (!ctx.info.ray_query) return;
  ray_query.rayQuery = VK_TRUE;
  ray_query.pNext = on.pNext;
  on.pNext = &ray_query;
}

// The device extensions enabled: ray tracing, and the optional ones the
// device has (describeDevice found them).
std::vector<const char*> deviceExtensions(const VulkanContext& ctx) {
  std::vector<const char*> extensions = {VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
                                         VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                                         VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};
  if (ctx.info.pipeline_library) extensions.push_back(VK_KHR_PIPELINE_LIBRARY_EXTENSION_NAME);
  if (ctx.info.graphics_pipeline_library)
    extensions.push_back(VK_EXT_GRAPHICS_PIPELINE_LIBRARY_EXTENSION_NAME);
  if (ctx.info.ray_tracing_maintenance1)
    extensions.push_back(VK_KHR_RAY_TRACING_MAINTENANCE_1_EXTENSION_NAME);
  if (ctx.position_fetch) extensions.push_back(kPositionFetchExtension);
  if (ctx.library_group_handles) extensions.push_back(kLibraryGroupHandlesExtension);
  if (ctx.info.ray_query) extensions.push_back(VK_KHR_RAY_QUERY_EXTENSION_NAME);
  if (ctx.info.invocation_reorder)
    extensions.push_back(VK_NV_RAY_TRACING_INVOCATION_REORDER_EXTENSION_NAME);
  // Its dependency synchronization2 is core from Vulkan 1.3.
  if (ctx.info.opacity_micromap && ctx.info.api_version_number >= VK_API_VERSION_1_3)
    extensions.push_back(VK_EXT_OPACITY_MICROMAP_EXTENSION_NAME);
  return extensions;
}

// The first queue family with compute (ray tracing runs there).
Result<void> chooseQueueFamily(VulkanContext& ctx) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physical, &count, families.data());
  for (uint32_t i = 0; i < count; ++i)
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
      ctx.queue_family = i;
      return {};
    }
  return deviceError("no compute queue family: VK_ERROR_FEATURE_NOT_PRESENT");
}

}  // namespace

Result<void> createDevice(VulkanContext& ctx) {
  RAYSPEC_TRY_VOID(chooseQueueFamily(ctx));

  // What the device supports.
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  VkPhysicalDeviceAccelerationStructureFeaturesKHR as{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 have{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  have.pNext = &v12;
  v12.pNext = &rt;
  rt.pNext = &as;
  vkGetPhysicalDeviceFeatures2(ctx.physical, &have);

  // What we enable.
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt_on{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  rt_on.rayTracingPipeline = VK_TRUE;
  rt_on.rayTraversalPrimitiveCulling = ctx.info.ray_traversal_primitive_culling;
  rt_on.rayTracingPipelineTraceRaysIndirect = ctx.info.trace_rays_indirect;
  VkPhysicalDeviceAccelerationStructureFeaturesKHR as_on{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  as_on.accelerationStructure = VK_TRUE;
  as_on.accelerationStructureIndirectBuild = ctx.info.acceleration_structure_indirect_build;
  // scene.build.query_command host (vkWriteAccelerationStructuresPropertiesKHR).
  as_on.accelerationStructureHostCommands = ctx.info.acceleration_structure_host_commands;
  VkPhysicalDeviceVulkan12Features v12_on{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  if (!v12.bufferDeviceAddress)
    return deviceError("bufferDeviceAddress not supported: VK_ERROR_FEATURE_NOT_PRESENT");
  v12_on.bufferDeviceAddress = VK_TRUE;
  v12_on.scalarBlockLayout = v12.scalarBlockLayout;
  ctx.info.scalar_block_layout = v12.scalarBlockLayout;
  v12_on.descriptorIndexing = v12.descriptorIndexing;  // rs_tlas[nonuniformEXT(i)]
  v12_on.vulkanMemoryModel = v12.vulkanMemoryModel;
  v12_on.vulkanMemoryModelDeviceScope = v12.vulkanMemoryModelDeviceScope;
  v12_on.shaderInt8 = v12.shaderInt8;  // the sized scalars (program/sized_types.h)
  v12_on.shaderFloat16 = v12.shaderFloat16;
  VkPhysicalDeviceRayTracingMaintenance1FeaturesKHR maintenance1_on{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_MAINTENANCE_1_FEATURES_KHR};
  maintenance1_on.rayTracingMaintenance1 = VK_TRUE;
  maintenance1_on.rayTracingPipelineTraceRaysIndirect2 = ctx.info.trace_rays_indirect2;
  VkPhysicalDeviceFeatures2 on{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  on.features.shaderInt64 = have.features.shaderInt64;
  on.features.shaderInt16 = have.features.shaderInt16;
  on.features.shaderFloat64 = have.features.shaderFloat64;
  on.features.sparseBinding = have.features.sparseBinding;  // scene.build.sparse
  on.pNext = &v12_on;
  v12_on.pNext = &rt_on;
  rt_on.pNext = &as_on;
  // gl_CullMaskEXT (the cull_mask built-in): describeDevice found the feature.
  if (ctx.info.ray_tracing_maintenance1) as_on.pNext = &maintenance1_on;
  PositionFetchFeatures position_fetch_on;
  LibraryGroupHandlesFeatures group_handles_on;
  enableNewerFeatures(ctx, on, position_fetch_on, group_handles_on);
  VkPhysicalDeviceRayQueryFeaturesKHR ray_query_on{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  enableRayQuery(ctx, on, ray_query_on);
  VkPhysicalDeviceRayTracingInvocationReorderFeaturesNV reorder_on{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_INVOCATION_REORDER_FEATURES_NV};
  enableInvocationReorder(ctx, on, reorder_on);

  const std::vector<const char*> extensions = deviceExtensions(ctx);
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueFamilyIndex = ctx.queue_family;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = &on;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  RAYSPEC_TRY_VOID(
      vkCheck(vkCreateDevice(ctx.physical, &info, nullptr, &ctx.device), "vkCreateDevice"));
  vkGetDeviceQueue(ctx.device, ctx.queue_family, 0, &ctx.queue);
  RAYSPEC_TRY(ctx.fn, loadDeviceFunctions(ctx.device));
  return {};
}

void destroyDevice(VulkanContext& ctx) {
  if (!ctx.device) return;
  vkDeviceWaitIdle(ctx.device);
  vkDestroyDevice(ctx.device, nullptr);
  ctx.device = VK_NULL_HANDLE;
}

}  // namespace rayspec
