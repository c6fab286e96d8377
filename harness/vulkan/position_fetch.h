// VK_KHR_ray_tracing_position_fetch (Vulkan 1.3.249): what rayspec needs of
// it. Debian 12's Vulkan headers (1.3.239) predate it, so its names are
// written here with their values from the registry (vk.xml, extension 482).
// Internal to harness/vulkan.
#pragma once

#include <vulkan/vulkan.h>

namespace rayspec {

constexpr const char* kPositionFetchExtension = "VK_KHR_ray_tracing_position_fetch";
constexpr auto kPositionFetchFeaturesType = static_cast<VkStructureType>(1000481000);
// The first header (and validation layer) version that knows the extension:
// an older layer rejects its SPIR-V capability and its feature structure.
constexpr uint32_t kPositionFetchHeaderVersion = VK_MAKE_API_VERSION(0, 1, 3, 249);

// VkPhysicalDeviceRayTracingPositionFetchFeaturesKHR, member for member
// (sType, pNext, rayTracingPositionFetch).
struct PositionFetchFeatures {
  VkStructureType s_type = kPositionFetchFeaturesType;
  void* p_next = nullptr;
  VkBool32 ray_tracing_position_fetch = VK_FALSE;
};

}  // namespace rayspec
