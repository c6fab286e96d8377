// Descriptor set 0 of a case: only the bindings of glsl/bindings.h the case
// uses (TLAS, rays, records, counters, scene data, one storage image each).
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include "vulkan/cleanup.h"
#include "vulkan/context.h"

namespace rayspec {

struct DescriptorItem {
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  VkBuffer buffer = VK_NULL_HANDLE;  // STORAGE_BUFFER (whole buffer)
  // ACCELERATION_STRUCTURE_KHR: one, or an array (the top levels by index)
  std::vector<VkAccelerationStructureKHR> tlases;
  VkImageView view = VK_NULL_HANDLE;  // STORAGE_IMAGE (layout GENERAL)
};

// Every item visible to all ray tracing stages.
Result<VkDescriptorSetLayout> createSetLayout(const VulkanContext& ctx,
                                              const std::vector<DescriptorItem>& items,
                                              Cleanup& cleanup);
// A pool sized for items, one set from it, written.
Result<VkDescriptorSet> createDescriptorSet(const VulkanContext& ctx, VkDescriptorSetLayout layout,
                                            const std::vector<DescriptorItem>& items,
                                            Cleanup& cleanup);

}  // namespace rayspec
