#include "vulkan/trace.h"

#include "glsl/emit_compute.h"
#include "vulkan/commands.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

// The stages that write the outputs: ray tracing shaders, or raygen run as a
// compute shader (Pipeline::from_compute).
constexpr VkPipelineStageFlags kShaderStages =
    VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;

VkStridedDeviceAddressRegionKHR region(VkDeviceAddress base, const SbtRegion& r) {
  if (r.size == 0) return {0, 0, 0};
  return {base + r.offset, r.stride, r.size};
}

VkImageMemoryBarrier imageBarrier(VkImage image, VkImageLayout from, VkImageLayout to,
                                  VkAccessFlags src, VkAccessFlags dst) {
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.srcAccessMask = src;
  b.dstAccessMask = dst;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  return b;
}

}  // namespace

void recordImageClears(VkCommandBuffer cmd, const std::vector<StorageImage>& images) {
  if (images.empty()) return;
  std::vector<VkImageMemoryBarrier> to_general, to_shader;
  for (const StorageImage& img : images) {
    to_general.push_back(imageBarrier(img.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                                      0, VK_ACCESS_TRANSFER_WRITE_BIT));
    to_shader.push_back(imageBarrier(img.image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                                     VK_ACCESS_TRANSFER_WRITE_BIT,
                                     VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT));
  }
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                       nullptr, 0, nullptr, static_cast<uint32_t>(to_general.size()),
                       to_general.data());
  VkClearColorValue zero{};
  VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  for (const StorageImage& img : images)
    vkCmdClearColorImage(cmd, img.image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, kShaderStages, 0, 0, nullptr, 0,
                       nullptr, static_cast<uint32_t>(to_shader.size()), to_shader.data());
}

Result<void> recordTrace(const VulkanContext& ctx, VkCommandBuffer cmd, const TraceBinding& bound,
                         const SbtLayout& sbt, VkDeviceAddress sbt_base, const Rays& rays,
                         Cleanup& cleanup) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, bound.pipeline);
  if (bound.set)  // none: pipeline.layout: empty
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, bound.layout, 0, 1,
                            &bound.set, 0, nullptr);
  if (bound.stack_size)
    ctx.fn.cmdSetRayTracingPipelineStackSize(cmd, static_cast<uint32_t>(*bound.stack_size));
  VkStridedDeviceAddressRegionKHR raygen = region(sbt_base, sbt.raygen);
  VkStridedDeviceAddressRegionKHR miss = region(sbt_base, sbt.miss);
  VkStridedDeviceAddressRegionKHR hit = region(sbt_base, sbt.hit);
  VkStridedDeviceAddressRegionKHR callable = region(sbt_base, sbt.callable);
  const std::array<uint32_t, 3> launch = rays.launchSize();
  const uint32_t width = launch[0], height = launch[1], depth = launch[2];
  constexpr VkBufferUsageFlags kUsage =
      VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  switch (rays.command) {
    case TraceCommand::Direct:
      ctx.fn.cmdTraceRays(cmd, &raygen, &miss, &hit, &callable, width, height, depth);
      return {};
    case TraceCommand::Indirect: {
      const VkTraceRaysIndirectCommandKHR size{width, height, depth};
      RAYSPEC_TRY(const Buffer b, createUploadBuffer(ctx, &size, sizeof size, kUsage, cleanup));
      ctx.fn.cmdTraceRaysIndirect(cmd, &raygen, &miss, &hit, &callable, b.address);
      return {};
    }
    case TraceCommand::Indirect2: {
      const VkTraceRaysIndirectCommand2KHR all{raygen.deviceAddress,
                                               raygen.size,
                                               miss.deviceAddress,
                                               miss.size,
                                               miss.stride,
                                               hit.deviceAddress,
                                               hit.size,
                                               hit.stride,
                                               callable.deviceAddress,
                                               callable.size,
                                               callable.stride,
                                               width,
                                               height,
                                               depth};
      RAYSPEC_TRY(const Buffer b, createUploadBuffer(ctx, &all, sizeof all, kUsage, cleanup));
      if (!ctx.fn.cmdTraceRaysIndirect2)
        return deviceError("vkGetDeviceProcAddr(vkCmdTraceRaysIndirect2KHR): missing");
      ctx.fn.cmdTraceRaysIndirect2(cmd, b.address);
      return {};
    }
  }
  return {};
}

void recordDispatch(VkCommandBuffer cmd, const TraceBinding& bound, const Rays& rays) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, bound.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, bound.layout, 0, 1, &bound.set, 0,
                          nullptr);
  const std::array<uint32_t, 3> groups = computeGroups(rays.launchSize());
  if (groups[0] != 0) vkCmdDispatch(cmd, groups[0], groups[1], groups[2]);
}

void recordReadback(VkCommandBuffer cmd, const std::vector<StorageImage>& images,
                    const std::vector<Buffer>& image_buffers, uint32_t width, uint32_t height) {
  recordMemoryBarrier(cmd, {kShaderStages, VK_ACCESS_SHADER_WRITE_BIT},
                      {VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_HOST_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT});
  if (images.empty()) return;
  for (size_t i = 0; i < images.size(); ++i) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {width, height, 1};
    vkCmdCopyImageToBuffer(cmd, images[i].image, VK_IMAGE_LAYOUT_GENERAL, image_buffers[i].buffer,
                           1, &copy);
  }
  recordMemoryBarrier(cmd, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                      {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
}

}  // namespace rayspec
