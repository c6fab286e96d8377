#include <algorithm>
#include <cctype>
#include <cstring>
#include <optional>
#include <vector>

#include "base/hex_text.h"
#include "vulkan/acceleration_structure.h"
#include "vulkan/context.h"
#include "vulkan/driver_id_name.h"
#include "vulkan/library_group_handles.h"
#include "vulkan/position_fetch.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

bool hasDeviceExtension(const std::vector<VkExtensionProperties>& exts, const char* name) {
  for (const VkExtensionProperties& e : exts)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return s;
}

// Appends a structure to a pNext chain whose end is *next.
template <typename T>
void chain(void**& next, T& s) {
  *next = &s;
  next = &s.pNext;
}

// The ray tracing and acceleration structure extensions the device lists.
void readExtensions(VkPhysicalDevice physical, DeviceInfo& d) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> exts(count);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, exts.data());
  d.ray_tracing_extension = hasDeviceExtension(exts, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
  d.acceleration_structure_extension =
      hasDeviceExtension(exts, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) &&
      hasDeviceExtension(exts, VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME);
  d.pipeline_library = hasDeviceExtension(exts, VK_KHR_PIPELINE_LIBRARY_EXTENSION_NAME);
  d.ray_query = hasDeviceExtension(exts, VK_KHR_RAY_QUERY_EXTENSION_NAME);
  d.opacity_micromap = hasDeviceExtension(exts, VK_EXT_OPACITY_MICROMAP_EXTENSION_NAME);
  d.ray_tracing_maintenance1 =
      hasDeviceExtension(exts, VK_KHR_RAY_TRACING_MAINTENANCE_1_EXTENSION_NAME);
  d.position_fetch = hasDeviceExtension(exts, kPositionFetchExtension);
  d.graphics_pipeline_library =
      d.pipeline_library &&
      hasDeviceExtension(exts, VK_EXT_GRAPHICS_PIPELINE_LIBRARY_EXTENSION_NAME);
  d.invocation_reorder =
      hasDeviceExtension(exts, VK_NV_RAY_TRACING_INVOCATION_REORDER_EXTENSION_NAME);
  d.library_group_handles =
      d.pipeline_library && hasDeviceExtension(exts, kLibraryGroupHandlesExtension);
}

// Vertex formats a device may build triangles from, named as in
// triangles.vertex_format: every format the Vulkan specification lets a
// device list for acceleration structures is one of rayspec's.
void readVertexFormats(VkPhysicalDevice physical, DeviceInfo& d) {
  if (!d.acceleration_structure_extension) return;
  for (VertexFormat f : enumValues<VertexFormat>()) {
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(physical, vkVertexFormat(f), &props);
    if (props.bufferFeatures & VK_FORMAT_FEATURE_ACCELERATION_STRUCTURE_VERTEX_BUFFER_BIT_KHR)
      d.vertex_formats.push_back(vertexFormatName(f));
  }
}

// Identity (UUIDs, driver) and the ray tracing pipeline's properties.
void readProperties(VkPhysicalDevice physical, DeviceInfo& d) {
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rt{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
  VkPhysicalDeviceAccelerationStructurePropertiesKHR as{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceIDProperties id{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ID_PROPERTIES};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  void** next = &props.pNext;
  const bool vk11 = d.api_version_number >= VK_API_VERSION_1_1;
  const bool vk12 = d.api_version_number >= VK_API_VERSION_1_2;
  if (vk11) chain(next, id);
  if (vk12) chain(next, driver);
  if (d.ray_tracing_extension) chain(next, rt);
  if (d.acceleration_structure_extension) chain(next, as);
  vkGetPhysicalDeviceProperties2(physical, &props);
  d.cpu = props.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  if (vk11)
    d.device_uuid =
        hexBytes(id.deviceUUID, VK_UUID_SIZE) + "-" + hexBytes(id.driverUUID, VK_UUID_SIZE);
  d.pipeline_cache_uuid = hexBytes(props.properties.pipelineCacheUUID, VK_UUID_SIZE);
  if (vk12) {
    d.driver_name = driver.driverName;
    d.driver_info = driver.driverInfo;
    const VkConformanceVersion& c = driver.conformanceVersion;
    d.conformance_version = std::to_string(c.major) + "." + std::to_string(c.minor) + "." +
                            std::to_string(c.subminor) + "." + std::to_string(c.patch);
    d.driver_id = driverIdName(driver.driverID);
  }
  if (d.ray_tracing_extension) {
    d.shader_group_handle_size = rt.shaderGroupHandleSize;
    d.shader_group_handle_alignment = rt.shaderGroupHandleAlignment;
    d.shader_group_base_alignment = rt.shaderGroupBaseAlignment;
    d.max_ray_recursion_depth = rt.maxRayRecursionDepth;
    d.max_ray_hit_attribute_size = rt.maxRayHitAttributeSize;
    d.max_shader_group_stride = rt.maxShaderGroupStride;
    d.max_ray_dispatch_invocation_count = rt.maxRayDispatchInvocationCount;
    d.shader_group_handle_capture_replay_size = rt.shaderGroupHandleCaptureReplaySize;
  }
  if (d.acceleration_structure_extension) {
    d.max_geometry_count = as.maxGeometryCount;
    d.max_instance_count = as.maxInstanceCount;
    d.max_primitive_count = as.maxPrimitiveCount;
    d.max_per_stage_descriptor_acceleration_structures =
        as.maxPerStageDescriptorAccelerationStructures;
    d.max_per_stage_descriptor_update_after_bind_acceleration_structures =
        as.maxPerStageDescriptorUpdateAfterBindAccelerationStructures;
    d.max_descriptor_set_acceleration_structures = as.maxDescriptorSetAccelerationStructures;
    d.max_descriptor_set_update_after_bind_acceleration_structures =
        as.maxDescriptorSetUpdateAfterBindAccelerationStructures;
    d.min_acceleration_structure_scratch_offset_alignment =
        as.minAccelerationStructureScratchOffsetAlignment;
  }
}

// The features the device has: ray tracing pipelines and acceleration
// structures (what rayspec needs) and the optional ones.
void readFeatures(VkPhysicalDevice physical, DeviceInfo& d) {
  VkPhysicalDeviceVulkan12Features v12_features{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt_features{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  VkPhysicalDeviceAccelerationStructureFeaturesKHR as_features{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingMaintenance1FeaturesKHR maintenance1{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_MAINTENANCE_1_FEATURES_KHR};
  VkPhysicalDeviceRayQueryFeaturesKHR ray_query{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  PositionFetchFeatures position_fetch;
  LibraryGroupHandlesFeatures group_handles;
  VkPhysicalDeviceRayTracingInvocationReorderFeaturesNV reorder{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_INVOCATION_REORDER_FEATURES_NV};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  void** next = &features.pNext;
  const bool vk12 = d.api_version_number >= VK_API_VERSION_1_2;
  if (vk12) chain(next, v12_features);
  if (d.ray_tracing_extension) chain(next, rt_features);
  if (d.acceleration_structure_extension) chain(next, as_features);
  if (d.ray_tracing_maintenance1) chain(next, maintenance1);
  if (d.ray_query) chain(next, ray_query);
  if (d.invocation_reorder) chain(next, reorder);
  if (d.position_fetch) {
    *next = &position_fetch;
    next = &position_fetch.p_next;
  }
  if (d.library_group_handles) {
    *next = &group_handles;
    next = &group_handles.p_next;
  }
  vkGetPhysicalDeviceFeatures2(physical, &features);
  d.scalar_block_layout = vk12 && v12_features.scalarBlockLayout;
  d.descriptor_indexing = vk12 && v12_features.descriptorIndexing;
  d.shader_int8 = vk12 && v12_features.shaderInt8;
  d.shader_float16 = vk12 && v12_features.shaderFloat16;
  d.shader_int16 = features.features.shaderInt16;
  d.shader_int64 = features.features.shaderInt64;
  d.shader_float64 = features.features.shaderFloat64;
  d.ray_tracing_pipeline = vk12 && d.ray_tracing_extension && rt_features.rayTracingPipeline;
  d.ray_traversal_primitive_culling =
      d.ray_tracing_pipeline && rt_features.rayTraversalPrimitiveCulling;
  d.acceleration_structure =
      vk12 && d.acceleration_structure_extension && as_features.accelerationStructure;
  d.acceleration_structure_host_commands =
      d.acceleration_structure_extension && as_features.accelerationStructureHostCommands;
  d.acceleration_structure_indirect_build =
      d.acceleration_structure_extension && as_features.accelerationStructureIndirectBuild;
  d.acceleration_structure_update_after_bind =
      d.acceleration_structure_extension &&
      as_features.descriptorBindingAccelerationStructureUpdateAfterBind;
  d.trace_rays_indirect = d.ray_tracing_pipeline && rt_features.rayTracingPipelineTraceRaysIndirect;
  d.trace_rays_indirect2 = d.ray_tracing_maintenance1 && d.ray_tracing_pipeline &&
                           maintenance1.rayTracingPipelineTraceRaysIndirect2;
  d.ray_tracing_maintenance1 = d.ray_tracing_maintenance1 && maintenance1.rayTracingMaintenance1;
  d.position_fetch =
      d.position_fetch && d.acceleration_structure && position_fetch.ray_tracing_position_fetch;
  d.library_group_handles = d.library_group_handles && group_handles.pipeline_library_group_handles;
  d.ray_query = d.ray_query && ray_query.rayQuery;
  d.invocation_reorder =
      d.invocation_reorder && d.ray_tracing_pipeline && reorder.rayTracingInvocationReorder;
  d.sparse_binding = features.features.sparseBinding;
}

// Whether the queue family rayspec runs on, the first with compute
// (vulkan/device.cpp), binds sparse memory.
void readQueues(VkPhysicalDevice physical, DeviceInfo& d) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
  for (const VkQueueFamilyProperties& f : families)
    if (f.queueFlags & VK_QUEUE_COMPUTE_BIT) {
      d.sparse_binding_queue = f.queueFlags & VK_QUEUE_SPARSE_BINDING_BIT;
      return;
    }
}

}  // namespace

std::string vulkanVersionText(uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) +
         "." + std::to_string(VK_API_VERSION_PATCH(v));
}

DeviceInfo describeDevice(VkPhysicalDevice physical, uint32_t index) {
  DeviceInfo d;
  d.index = index;
  VkPhysicalDeviceProperties base{};
  vkGetPhysicalDeviceProperties(physical, &base);
  d.name = base.deviceName;
  d.api_version = vulkanVersionText(base.apiVersion);
  d.api_version_number = base.apiVersion;
  d.max_image_dimension_2d = base.limits.maxImageDimension2D;
  d.max_storage_buffer_range = base.limits.maxStorageBufferRange;
  for (int k = 0; k < 3; ++k)
    d.max_launch_size[k] =
        uint64_t(base.limits.maxComputeWorkGroupCount[k]) * base.limits.maxComputeWorkGroupSize[k];
  readExtensions(physical, d);
  readProperties(physical, d);
  readFeatures(physical, d);
  readQueues(physical, d);
  readVertexFormats(physical, d);
  return d;
}

Result<void> selectDevice(VulkanContext& ctx, const std::string& filter) {
  RAYSPEC_TRY(const std::vector<VkPhysicalDevice> physicals, physicalDevices(ctx.instance));
  const uint32_t count = static_cast<uint32_t>(physicals.size());
  std::string seen;
  for (uint32_t i = 0; i < count; ++i) {
    DeviceInfo d = describeDevice(physicals[i], i);
    if (!filter.empty() && lower(d.name).find(lower(filter)) == std::string::npos) continue;
    if (!d.ray_tracing_pipeline || !d.acceleration_structure) {
      seen += (seen.empty() ? "" : ", ") + d.name;
      continue;
    }
    ctx.physical = physicals[i];
    ctx.info = d;
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props.pNext = &ctx.rt_props;
    ctx.rt_props.pNext = &ctx.as_props;
    ctx.as_props.pNext = nullptr;
    vkGetPhysicalDeviceProperties2(ctx.physical, &props);
    ctx.rt_props.pNext = nullptr;
    ctx.props = props.properties;
    vkGetPhysicalDeviceMemoryProperties(ctx.physical, &ctx.memory);
    return {};
  }
  std::string why =
      "no Vulkan device with VK_KHR_ray_tracing_pipeline and VK_KHR_acceleration_structure";
  if (!filter.empty()) why += " whose name contains '" + filter + "'";
  if (!seen.empty()) why += " (without ray tracing: " + seen + ")";
  return errorMessage(why);
}

namespace {

// Every physical device of a new instance in ctx (which the caller destroys).
Result<std::vector<DeviceInfo>> describeAll(VulkanContext& ctx) {
  RAYSPEC_TRY_VOID(createInstance(ctx, false));
  RAYSPEC_TRY(const std::vector<VkPhysicalDevice> physicals, physicalDevices(ctx.instance));
  std::vector<DeviceInfo> out;
  for (uint32_t i = 0; i < physicals.size(); ++i) out.push_back(describeDevice(physicals[i], i));
  return out;
}

}  // namespace

Result<std::vector<DeviceInfo>> listDevices() {
  VulkanContext ctx;
  Result<std::vector<DeviceInfo>> out = describeAll(ctx);
  destroyInstance(ctx);
  return out;
}

}  // namespace rayspec
