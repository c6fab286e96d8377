// Recording of the launch: storage image preparation, vkCmdTraceRaysKHR, and
// the copies and barriers that make the outputs readable on the host.
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include "case/case.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/memory.h"
#include "vulkan/sbt_layout.h"

namespace rayspec {

// UNDEFINED -> GENERAL, cleared to zero, visible to ray tracing shaders.
void recordImageClears(VkCommandBuffer cmd, const std::vector<StorageImage>& images);

// Binds the pipeline and set 0, traces width x height x 1 with the SBT at
// sbt_base (base-aligned) laid out as layout, by the command the case names
// (rays.command): vkCmdTraceRaysKHR, or vkCmdTraceRaysIndirectKHR /
// vkCmdTraceRaysIndirect2KHR reading a buffer (made here, freed by cleanup)
// that holds the launch size, and for indirect2 the SBT regions too.
void recordTrace(const VulkanContext& ctx, VkCommandBuffer cmd, VkPipeline pipeline,
                 VkPipelineLayout layout, VkDescriptorSet set, const SbtLayout& sbt,
                 VkDeviceAddress sbt_base, const Rays& rays, Cleanup& cleanup);

// Shader writes -> host reads, and each image copied into its host buffer
// (tightly packed rows).
void recordReadback(VkCommandBuffer cmd, const std::vector<StorageImage>& images,
                    const std::vector<Buffer>& image_buffers, uint32_t width, uint32_t height);

}  // namespace rayspec
