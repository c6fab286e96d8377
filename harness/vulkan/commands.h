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

}  // namespace rayspec
