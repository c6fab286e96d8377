#include "vulkan/sbt_buffer.h"

#include <cstring>

#include "vulkan/memory.h"
#include "vulkan/pipeline.h"
#include "vulkan/vk_check.h"

namespace rayspec {

SbtLimits deviceSbtLimits(const VulkanContext& ctx) {
  return sbtLimits(ctx.info);
}

Result<SbtBuffer> createSbtBuffer(const VulkanContext& ctx, const Pipeline& p,
                                  const RayTracingPipeline& pipeline, Cleanup& cleanup) {
  SbtLimits limits = deviceSbtLimits(ctx);
  SbtBuffer out;
  out.layout = computeSbtLayout(limits, p);
  if (const Result<void> fits = checkSbtLayout(out.layout, limits); !fits)
    return notSupported(fits.error().format());
  RAYSPEC_TRY(const std::vector<uint8_t> handles, groupHandles(ctx, pipeline));
  const Result<std::vector<uint8_t>> table = writeSbt(out.layout, limits, p, handles);
  if (!table) return deviceError(table.error().format() + ": VK_ERROR_UNKNOWN");
  const std::vector<uint8_t>& bytes = *table;
  RAYSPEC_TRY(const Buffer buffer, createBuffer(ctx, bytes.size() + limits.base_alignment,
                                                VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR |
                                                    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                                MemoryUse::Host, cleanup));
  out.base = alignUp(buffer.address, limits.base_alignment);
  std::memcpy(static_cast<uint8_t*>(buffer.mapped) + (out.base - buffer.address), bytes.data(),
              bytes.size());
  return out;
}

}  // namespace rayspec
