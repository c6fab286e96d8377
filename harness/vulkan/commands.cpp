#include "vulkan/commands.h"

#include "vulkan/vk_check.h"

namespace rayspec {

Result<VkCommandBuffer> beginCommands(const VulkanContext& ctx, Cleanup& cleanup) {
  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pool_info.queueFamilyIndex = ctx.queue_family;
  VkCommandPool pool = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(
      vkCheck(vkCreateCommandPool(ctx.device, &pool_info, nullptr, &pool), "vkCreateCommandPool"));
  VkDevice device = ctx.device;
  cleanup.add([device, pool] { vkDestroyCommandPool(device, pool, nullptr); });

  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(
      vkCheck(vkAllocateCommandBuffers(ctx.device, &alloc, &cmd), "vkAllocateCommandBuffers"));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  RAYSPEC_TRY_VOID(vkCheck(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer"));
  return cmd;
}

Result<void> submitAndWait(const VulkanContext& ctx, VkCommandBuffer cmd) {
  RAYSPEC_TRY_VOID(vkCheck(vkEndCommandBuffer(cmd), "vkEndCommandBuffer"));
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(
      vkCheck(vkCreateFence(ctx.device, &fence_info, nullptr, &fence), "vkCreateFence"));
  Cleanup local;
  VkDevice device = ctx.device;
  VkQueue queue = ctx.queue;
  // The fence may go only once the queue is done with it: when the wait
  // failed (a timeout, a lost device) the submission may still be running.
  local.add([device, queue, fence] {
    vkQueueWaitIdle(queue);
    vkDestroyFence(device, fence, nullptr);
  });
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  RAYSPEC_TRY_VOID(vkCheck(vkQueueSubmit(ctx.queue, 1, &submit, fence), "vkQueueSubmit"));
  RAYSPEC_TRY_VOID(vkCall("vkWaitForFences", [&] {
    return vkWaitForFences(ctx.device, 1, &fence, VK_TRUE, ctx.wait_timeout_ns);
  }));
  return {};
}

void recordMemoryBarrier(VkCommandBuffer cmd, StageAccess src, StageAccess dst) {
  VkMemoryBarrier mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  mb.srcAccessMask = src.access;
  mb.dstAccessMask = dst.access;
  vkCmdPipelineBarrier(cmd, src.stages, dst.stages, 0, 1, &mb, 0, nullptr, 0, nullptr);
}

}  // namespace rayspec
