// VK_EXT_pipeline_library_group_handles (Vulkan 1.3.240): group handles read
// from a pipeline library, bitwise identical to those of the pipelines that
// link it (its pipelineLibraryGroupHandles feature). Debian 12's headers and
// validation layer (1.3.239) predate it, so its names are written here with
// their values from the registry (vk.xml, extension 499). Internal to
// harness/vulkan.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "base/result.h"

namespace rayspec {

struct VulkanContext;
struct RayTracingPipeline;

constexpr const char* kLibraryGroupHandlesExtension = "VK_EXT_pipeline_library_group_handles";
constexpr auto kLibraryGroupHandlesFeaturesType = static_cast<VkStructureType>(1000498000);
// The first header (and validation layer) version that knows the extension.
constexpr uint32_t kLibraryGroupHandlesHeaderVersion = VK_MAKE_API_VERSION(0, 1, 3, 240);

// VkPhysicalDevicePipelineLibraryGroupHandlesFeaturesEXT, member for member
// (sType, pNext, pipelineLibraryGroupHandles).
struct LibraryGroupHandlesFeatures {
  VkStructureType s_type = kLibraryGroupHandlesFeaturesType;
  void* p_next = nullptr;
  VkBool32 pipeline_library_group_handles = VK_FALSE;
};

// R-LIBRARY with the feature enabled: every group that lives in a library,
// its handle read from that library against its handle in the linked
// pipeline; one line for each that differs (empty: all identical, or the
// pipeline links no library), or the Device error of a handle query.
// *compared: how many groups were compared.
Result<std::vector<std::string>> libraryHandleMismatches(const VulkanContext& ctx,
                                                         const RayTracingPipeline& pipeline,
                                                         uint32_t* compared);

}  // namespace rayspec
