#include "vulkan/memory.h"

#include <cstring>

#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

uint32_t findMemoryType(const VulkanContext& ctx, uint32_t type_bits,
                        VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) {
  for (int pass = 0; pass < 2; ++pass) {
    VkMemoryPropertyFlags want = pass == 0 ? (required | preferred) : required;
    for (uint32_t i = 0; i < ctx.memory.memoryTypeCount; ++i) {
      if (!(type_bits & (1u << i))) continue;
      if ((ctx.memory.memoryTypes[i].propertyFlags & want) == want) return i;
    }
  }
  throw VulkanError("no memory type fits: VK_ERROR_OUT_OF_DEVICE_MEMORY");
}

VkDeviceMemory allocate(const VulkanContext& ctx, const VkMemoryRequirements& req, MemoryUse use,
                        bool device_address) {
  VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.pNext = device_address ? &flags : nullptr;
  info.allocationSize = req.size;
  info.memoryTypeIndex =
      use == MemoryUse::Host
          ? findMemoryType(
                ctx, req.memoryTypeBits,
                VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, 0)
          : findMemoryType(ctx, req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  vkCall("vkAllocateMemory", [&] { return vkAllocateMemory(ctx.device, &info, nullptr, &memory); });
  return memory;
}

}  // namespace

Buffer createBuffer(const VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                    MemoryUse use, Cleanup& cleanup) {
  Buffer b;
  b.size = size;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size < 16 ? 16 : size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkDevice device = ctx.device;
  vkCheck(vkCreateBuffer(device, &info, nullptr, &b.buffer), "vkCreateBuffer");
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(device, b.buffer, &req);
  bool device_address = usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  try {
    b.memory = allocate(ctx, req, use, device_address);
  } catch (...) {
    vkDestroyBuffer(device, b.buffer, nullptr);
    throw;
  }
  VkBuffer buffer = b.buffer;
  VkDeviceMemory memory = b.memory;
  cleanup.add([device, buffer, memory] {
    vkDestroyBuffer(device, buffer, nullptr);
    vkFreeMemory(device, memory, nullptr);
  });
  vkCheck(vkBindBufferMemory(device, b.buffer, b.memory, 0), "vkBindBufferMemory");
  if (use == MemoryUse::Host)
    vkCheck(vkMapMemory(device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
  if (device_address) {
    VkBufferDeviceAddressInfo ai{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    ai.buffer = b.buffer;
    b.address = vkGetBufferDeviceAddress(device, &ai);
  }
  return b;
}

Buffer createUploadBuffer(const VulkanContext& ctx, const void* data, VkDeviceSize bytes,
                          VkBufferUsageFlags usage, Cleanup& cleanup) {
  Buffer b = createBuffer(ctx, bytes, usage, MemoryUse::Host, cleanup);
  if (bytes) std::memcpy(b.mapped, data, bytes);
  return b;
}

StorageImage createStorageImage(const VulkanContext& ctx, uint32_t width, uint32_t height,
                                VkFormat format, Cleanup& cleanup) {
  StorageImage img;
  img.format = format;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
               VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkDevice device = ctx.device;
  vkCheck(vkCreateImage(device, &info, nullptr, &img.image), "vkCreateImage");
  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(device, img.image, &req);
  try {
    img.memory = allocate(ctx, req, MemoryUse::Device, false);
  } catch (...) {
    vkDestroyImage(device, img.image, nullptr);
    throw;
  }
  VkImage image = img.image;
  VkDeviceMemory memory = img.memory;
  cleanup.add([device, image, memory] {
    vkDestroyImage(device, image, nullptr);
    vkFreeMemory(device, memory, nullptr);
  });
  vkCheck(vkBindImageMemory(device, img.image, img.memory, 0), "vkBindImageMemory");

  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = img.image;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = format;
  view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCheck(vkCreateImageView(device, &view, nullptr, &img.view), "vkCreateImageView");
  VkImageView v = img.view;
  cleanup.add([device, v] { vkDestroyImageView(device, v, nullptr); });
  return img;
}

}  // namespace rayspec
