#include "vulkan/descriptors.h"

#include <map>

#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

// Compute too: raygen may run as a compute shader (Pipeline::from_compute).
constexpr VkShaderStageFlags kShaderStages =
    VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR |
    VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_ANY_HIT_BIT_KHR |
    VK_SHADER_STAGE_INTERSECTION_BIT_KHR | VK_SHADER_STAGE_CALLABLE_BIT_KHR |
    VK_SHADER_STAGE_COMPUTE_BIT;

// An array of top levels for the TLAS binding, one descriptor elsewhere.
uint32_t descriptorCount(const DescriptorItem& it) {
  return it.type == VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR
             ? static_cast<uint32_t>(it.tlases.size())
             : 1;
}

}  // namespace

Result<VkDescriptorSetLayout> createSetLayout(const VulkanContext& ctx,
                                              const std::vector<DescriptorItem>& items,
                                              Cleanup& cleanup) {
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const DescriptorItem& it : items) {
    VkDescriptorSetLayoutBinding b{};
    b.binding = it.binding;
    b.descriptorType = it.type;
    b.descriptorCount = descriptorCount(it);
    b.stageFlags = kShaderStages;
    bindings.push_back(b);
  }
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = static_cast<uint32_t>(bindings.size());
  info.pBindings = bindings.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(vkCheck(vkCreateDescriptorSetLayout(ctx.device, &info, nullptr, &layout),
                           "vkCreateDescriptorSetLayout"));
  VkDevice device = ctx.device;
  cleanup.add([device, layout] { vkDestroyDescriptorSetLayout(device, layout, nullptr); });
  return layout;
}

Result<VkDescriptorSet> createDescriptorSet(const VulkanContext& ctx, VkDescriptorSetLayout layout,
                                            const std::vector<DescriptorItem>& items,
                                            Cleanup& cleanup) {
  std::map<VkDescriptorType, uint32_t> counts;
  for (const DescriptorItem& it : items) counts[it.type] += descriptorCount(it);
  std::vector<VkDescriptorPoolSize> sizes;
  for (const auto& [type, n] : counts) sizes.push_back({type, n});
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = static_cast<uint32_t>(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(vkCheck(vkCreateDescriptorPool(ctx.device, &pool_info, nullptr, &pool),
                           "vkCreateDescriptorPool"));
  VkDevice device = ctx.device;
  cleanup.add([device, pool] { vkDestroyDescriptorPool(device, pool, nullptr); });

  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(
      vkCheck(vkAllocateDescriptorSets(ctx.device, &alloc, &set), "vkAllocateDescriptorSets"));

  // Stable storage for the pointed-to infos.
  std::vector<VkDescriptorBufferInfo> buffers(items.size());
  std::vector<VkDescriptorImageInfo> images(items.size());
  std::vector<VkWriteDescriptorSetAccelerationStructureKHR> structures(items.size());
  std::vector<VkWriteDescriptorSet> writes;
  for (size_t i = 0; i < items.size(); ++i) {
    const DescriptorItem& it = items[i];
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = it.binding;
    w.descriptorCount = descriptorCount(it);
    w.descriptorType = it.type;
    if (it.type == VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR) {
      structures[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
      structures[i].accelerationStructureCount = w.descriptorCount;
      structures[i].pAccelerationStructures = it.tlases.data();
      w.pNext = &structures[i];
    } else if (it.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE) {
      images[i] = {VK_NULL_HANDLE, it.view, VK_IMAGE_LAYOUT_GENERAL};
      w.pImageInfo = &images[i];
    } else {
      buffers[i] = {it.buffer, 0, VK_WHOLE_SIZE};
      w.pBufferInfo = &buffers[i];
    }
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(ctx.device, static_cast<uint32_t>(writes.size()), writes.data(), 0,
                         nullptr);
  return set;
}

}  // namespace rayspec
