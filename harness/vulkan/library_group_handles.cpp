#include "vulkan/library_group_handles.h"

#include <cstring>

#include "vulkan/context.h"
#include "vulkan/pipeline.h"
#include "vulkan/vk_check.h"

namespace rayspec {

Result<std::vector<std::string>> libraryHandleMismatches(const VulkanContext& ctx,
                                                         const RayTracingPipeline& pipeline,
                                                         uint32_t* compared) {
  const uint32_t size = ctx.rt_props.shaderGroupHandleSize;
  std::vector<std::string> out;
  std::vector<uint8_t> from_library(size), linked(size);
  for (uint32_t group = 0; group < pipeline.group_site.size(); ++group) {
    const GroupSite& site = pipeline.group_site[group];
    if (site.pipeline == VK_NULL_HANDLE || site.pipeline == pipeline.pipeline) continue;
    RAYSPEC_TRY_VOID(
        vkCheck(ctx.fn.getRayTracingShaderGroupHandles(ctx.device, site.pipeline, site.index, 1,
                                                       size, from_library.data()),
                "vkGetRayTracingShaderGroupHandlesKHR (library)"));
    RAYSPEC_TRY_VOID(vkCheck(
        ctx.fn.getRayTracingShaderGroupHandles(
            ctx.device, pipeline.pipeline, pipeline.group_index.at(group), 1, size, linked.data()),
        "vkGetRayTracingShaderGroupHandlesKHR"));
    ++*compared;
    if (std::memcmp(from_library.data(), linked.data(), size) != 0)
      out.push_back("group " + std::to_string(group) + " (library group " +
                    std::to_string(site.index) +
                    "): its handle read from the library differs "
                    "from its handle in the linked pipeline (group " +
                    std::to_string(pipeline.group_index.at(group)) +
                    "); VK_EXT_pipeline_library_group_handles makes them bitwise identical");
  }
  return out;
}

}  // namespace rayspec
