#include "vulkan/address_table.h"

#include <algorithm>

#include "glsl/bindings.h"
#include "vulkan/acceleration_structure.h"
#include "vulkan/memory.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

Result<VkDeviceAddress> itemAddress(const VulkanContext& ctx, const DescriptorItem& item) {
  if (item.type == VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR && item.tlases.size() == 1)
    return structureAddress(ctx, item.tlases[0]);
  if (item.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER) return bufferAddress(ctx.device, item.buffer);
  return deviceError("binding " + std::to_string(item.binding) +
                     " has no device address for an empty pipeline layout: VK_ERROR_UNKNOWN");
}

void specialize(CompiledShader& s, VkDeviceAddress table) {
  s.specialization.emplace_back(kTableLowConstantId, static_cast<uint32_t>(table));
  s.specialization.emplace_back(kTableHighConstantId, static_cast<uint32_t>(table >> 32));
}

}  // namespace

Result<VkDeviceAddress> createAddressTable(const VulkanContext& ctx,
                                           const std::vector<DescriptorItem>& items,
                                           Cleanup& cleanup) {
  uint32_t slots = 0;
  for (const DescriptorItem& item : items) slots = std::max(slots, item.binding + 1);
  std::vector<uint64_t> table(slots, 0);
  for (const DescriptorItem& item : items) {
    RAYSPEC_TRY(table[item.binding], itemAddress(ctx, item));
  }
  RAYSPEC_TRY(const Buffer b, createUploadBuffer(ctx, table.data(), table.size() * 8,
                                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                     VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                                 cleanup));
  return b.address;
}

void specializeTableAddress(CompiledPipeline& compiled, VkDeviceAddress table) {
  specialize(compiled.raygen, table);
  for (CompiledShader& s : compiled.other_raygens) specialize(s, table);
  for (CompiledShader& s : compiled.miss) specialize(s, table);
  for (CompiledGroup& g : compiled.hit_groups)
    for (std::optional<CompiledShader>* s : {&g.closest_hit, &g.any_hit, &g.intersection})
      if (*s) specialize(**s, table);
  for (CompiledShader& s : compiled.callables) specialize(s, table);
}

}  // namespace rayspec
