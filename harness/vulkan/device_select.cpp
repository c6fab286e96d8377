#include <algorithm>
#include <cctype>
#include <cstring>
#include <vector>

#include "vulkan/context.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

bool hasDeviceExtension(const std::vector<VkExtensionProperties>& exts, const char* name) {
  for (const VkExtensionProperties& e : exts)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

std::string versionString(uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) +
         "." + std::to_string(VK_API_VERSION_PATCH(v));
}

std::string hexBytes(const uint8_t* bytes, size_t n) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out;
  for (size_t i = 0; i < n; ++i) out += {kDigits[bytes[i] >> 4], kDigits[bytes[i] & 15]};
  return out;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return s;
}

}  // namespace

DeviceInfo describeDevice(VkPhysicalDevice physical, uint32_t index) {
  DeviceInfo d;
  d.index = index;
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> exts(count);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, exts.data());
  bool rt_ext = hasDeviceExtension(exts, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
  bool as_ext = hasDeviceExtension(exts, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) &&
                hasDeviceExtension(exts, VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME);

  VkPhysicalDeviceProperties base{};
  vkGetPhysicalDeviceProperties(physical, &base);
  d.name = base.deviceName;
  d.api_version = versionString(base.apiVersion);
  d.api_version_number = base.apiVersion;
  d.ray_tracing_extension = rt_ext;
  d.acceleration_structure_extension = as_ext;
  bool vk12 = base.apiVersion >= VK_API_VERSION_1_2;

  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rt{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
  VkPhysicalDeviceAccelerationStructurePropertiesKHR as{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceIDProperties id{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ID_PROPERTIES};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  void** next = &props.pNext;
  const bool vk11 = base.apiVersion >= VK_API_VERSION_1_1;
  if (vk11) { *next = &id; next = &id.pNext; }
  if (vk12) { *next = &driver; next = &driver.pNext; }
  if (rt_ext) { *next = &rt; next = &rt.pNext; }
  if (as_ext) { *next = &as; next = &as.pNext; }
  vkGetPhysicalDeviceProperties2(physical, &props);
  d.cpu = props.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  if (vk11) d.device_uuid = hexBytes(id.deviceUUID, VK_UUID_SIZE) + "-" + hexBytes(id.driverUUID, VK_UUID_SIZE);
  if (vk12) {
    d.driver_name = driver.driverName;
    d.driver_info = driver.driverInfo;
  }

  VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt_features{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  VkPhysicalDeviceAccelerationStructureFeaturesKHR as_features{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  next = &features.pNext;
  if (rt_ext) { *next = &rt_features; next = &rt_features.pNext; }
  if (as_ext) { *next = &as_features; next = &as_features.pNext; }
  vkGetPhysicalDeviceFeatures2(physical, &features);

  d.ray_tracing_pipeline = vk12 && rt_ext && rt_features.rayTracingPipeline;
  d.acceleration_structure = vk12 && as_ext && as_features.accelerationStructure;
  if (rt_ext) {
    d.shader_group_handle_size = rt.shaderGroupHandleSize;
    d.shader_group_handle_alignment = rt.shaderGroupHandleAlignment;
    d.shader_group_base_alignment = rt.shaderGroupBaseAlignment;
    d.max_ray_recursion_depth = rt.maxRayRecursionDepth;
    d.max_ray_hit_attribute_size = rt.maxRayHitAttributeSize;
    d.max_shader_group_stride = rt.maxShaderGroupStride;
    d.max_ray_dispatch_invocation_count = rt.maxRayDispatchInvocationCount;
  }
  d.acceleration_structure_host_commands = as_ext && as_features.accelerationStructureHostCommands;
  d.max_image_dimension_2d = base.limits.maxImageDimension2D;
  d.max_storage_buffer_range = base.limits.maxStorageBufferRange;
  for (int k = 0; k < 3; ++k)
    d.max_launch_size[k] = uint64_t(base.limits.maxComputeWorkGroupCount[k]) * base.limits.maxComputeWorkGroupSize[k];
  return d;
}

bool selectDevice(VulkanContext& ctx, const std::string& filter, std::string* error) {
  uint32_t count = 0;
  vkCheck(vkEnumeratePhysicalDevices(ctx.instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> physicals(count);
  vkCheck(vkEnumeratePhysicalDevices(ctx.instance, &count, physicals.data()),
          "vkEnumeratePhysicalDevices");
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
    return true;
  }
  if (error) {
    *error = "no Vulkan device with VK_KHR_ray_tracing_pipeline and VK_KHR_acceleration_structure";
    if (!filter.empty()) *error += " whose name contains '" + filter + "'";
    if (!seen.empty()) *error += " (without ray tracing: " + seen + ")";
  }
  return false;
}

std::vector<DeviceInfo> listDevices(std::string* error) {
  std::vector<DeviceInfo> out;
  VulkanContext ctx;
  try {
    createInstance(ctx, false);
    uint32_t count = 0;
    vkCheck(vkEnumeratePhysicalDevices(ctx.instance, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> physicals(count);
    vkCheck(vkEnumeratePhysicalDevices(ctx.instance, &count, physicals.data()),
            "vkEnumeratePhysicalDevices");
    for (uint32_t i = 0; i < count; ++i) out.push_back(describeDevice(physicals[i], i));
  } catch (const std::exception& e) {
    if (error) *error = e.what();
  }
  destroyInstance(ctx);
  return out;
}

}  // namespace rayspec
