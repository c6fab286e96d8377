// Recording of the launch: storage image preparation, vkCmdTraceRaysKHR, and
// the copies and barriers that make the outputs readable on the host.
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <vector>

#include "case/case.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/memory.h"
#include "vulkan/sbt_layout.h"

namespace rayspec {

// UNDEFINED -> GENERAL, cleared to zero, visible to ray tracing shaders.
void recordImageClears(VkCommandBuffer cmd, const std::vector<StorageImage>& images);

// What a trace binds: the pipeline, its layout and set 0, and where the case
// sets one (pipeline.callable_depth, R-STACK), the pipeline stack size.
struct TraceBinding {
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  std::optional<VkDeviceSize> stack_size;  // vkCmdSetRayTracingPipelineStackSizeKHR
};

// Binds `bound`, traces rays.launch (width x height x depth) with the SBT at sbt_base
// (base-aligned) laid out as layout, by the command the case names
// (rays.command): vkCmdTraceRaysKHR, or vkCmdTraceRaysIndirectKHR /
// vkCmdTraceRaysIndirect2KHR reading a buffer (made here, freed by cleanup)
// that holds the launch size, and for indirect2 the SBT regions too. Or the
// Device error.
Result<void> recordTrace(const VulkanContext& ctx, VkCommandBuffer cmd, const TraceBinding& bound,
                         const SbtLayout& sbt, VkDeviceAddress sbt_base, const Rays& rays,
                         Cleanup& cleanup);

// Raygen run as a compute shader (Pipeline::from_compute): binds `bound`'s
// compute pipeline and set 0 and dispatches the groups that cover
// rays.launch (glsl/emit_compute.h); whatever rays.command says, the launch
// is one vkCmdDispatch.
void recordDispatch(VkCommandBuffer cmd, const TraceBinding& bound, const Rays& rays);

// Shader writes -> host reads, and each image copied into its host buffer
// (tightly packed rows).
void recordReadback(VkCommandBuffer cmd, const std::vector<StorageImage>& images,
                    const std::vector<Buffer>& image_buffers, uint32_t width, uint32_t height);

}  // namespace rayspec
