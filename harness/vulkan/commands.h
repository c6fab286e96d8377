// One primary command buffer per case, submitted once and waited on.
#pragma once

#include <vulkan/vulkan.h>

#include "vulkan/cleanup.h"
#include "vulkan/context.h"

namespace rayspec {

// A command pool + command buffer (destroyed through cleanup), begun for one submit.
Result<VkCommandBuffer> beginCommands(const VulkanContext& ctx, Cleanup& cleanup);
// vkEndCommandBuffer, vkQueueSubmit with a fence, wait (ctx.wait_timeout_ns);
// the Device error of the call that failed (VK_TIMEOUT when the device did
// not finish in time).
Result<void> submitAndWait(const VulkanContext& ctx, VkCommandBuffer cmd);

// The stage of acceleration structure builds, updates and copies.
constexpr VkPipelineStageFlags kBuildStage = VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR;

// One global memory barrier: the src stages' src accesses made available to,
// and visible for, the dst stages' dst accesses.
struct StageAccess {
  VkPipelineStageFlags stages;
  VkAccessFlags access;
};
void recordMemoryBarrier(VkCommandBuffer cmd, StageAccess src, StageAccess dst);

}  // namespace rayspec
