#include "vulkan/acceleration_copy.h"

#include "vulkan/acceleration_structure.h"
#include "vulkan/commands.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

// The compacted size of each structure, as the device reports it.
std::vector<VkDeviceSize> compactedSizes(const VulkanContext& ctx,
                                         const std::vector<BuiltStructure>& from,
                                         Cleanup& cleanup) {
  const uint32_t count = static_cast<uint32_t>(from.size());
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR;
  info.queryCount = count;
  VkQueryPool pool = VK_NULL_HANDLE;
  vkCheck(vkCreateQueryPool(ctx.device, &info, nullptr, &pool), "vkCreateQueryPool");
  VkDevice device = ctx.device;
  cleanup.add([device, pool] { vkDestroyQueryPool(device, pool, nullptr); });
  std::vector<VkAccelerationStructureKHR> handles;
  for (const BuiltStructure& s : from) handles.push_back(s.handle);
  VkCommandBuffer cmd = beginCommands(ctx, cleanup);
  vkCmdResetQueryPool(cmd, pool, 0, count);
  ctx.fn.cmdWriteAccelerationStructuresProperties(
      cmd, count, handles.data(), VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, pool, 0);
  submitAndWait(ctx, cmd, kBuildTimeoutNs);
  std::vector<VkDeviceSize> sizes(count);
  vkCheck(vkGetQueryPoolResults(ctx.device, pool, 0, count, count * sizeof(VkDeviceSize),
                                sizes.data(), sizeof(VkDeviceSize),
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "vkGetQueryPoolResults");
  for (size_t i = 0; i < count; ++i)
    if (sizes[i] == 0 || sizes[i] > from[i].size)
      throw VulkanError("compacted size " + std::to_string(sizes[i]) + " of a structure of " +
                        std::to_string(from[i].size) + " bytes: VK_ERROR_UNKNOWN");
  return sizes;
}

}  // namespace

std::vector<BuiltStructure> copyStructures(const VulkanContext& ctx,
                                           const std::vector<BuiltStructure>& from,
                                           VkAccelerationStructureTypeKHR type, AsCopy mode,
                                           Cleanup& cleanup) {
  if (from.empty() || mode == AsCopy::None) return from;
  std::vector<VkDeviceSize> sizes;
  for (const BuiltStructure& s : from) sizes.push_back(s.size);
  if (mode == AsCopy::Compact) sizes = compactedSizes(ctx, from, cleanup);
  std::vector<BuiltStructure> to;
  VkCommandBuffer cmd = beginCommands(ctx, cleanup);
  for (size_t i = 0; i < from.size(); ++i) {
    to.push_back({createStructure(ctx, type, sizes[i], cleanup), sizes[i]});
    VkCopyAccelerationStructureInfoKHR copy{VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR};
    copy.src = from[i].handle;
    copy.dst = to.back().handle;
    copy.mode = mode == AsCopy::Compact ? VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR
                                        : VK_COPY_ACCELERATION_STRUCTURE_MODE_CLONE_KHR;
    ctx.fn.cmdCopyAccelerationStructure(cmd, &copy);
  }
  recordStructureBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR |
                                  VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);
  submitAndWait(ctx, cmd, kBuildTimeoutNs);
  return to;
}

}  // namespace rayspec
