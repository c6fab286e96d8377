#include "vulkan/memory.h"

#include <algorithm>
#include <cstring>

#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

Result<uint32_t> findMemoryType(const VulkanContext& ctx, uint32_t type_bits,
                                VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) {
  for (int pass = 0; pass < 2; ++pass) {
    VkMemoryPropertyFlags want = pass == 0 ? (required | preferred) : required;
    for (uint32_t i = 0; i < ctx.memory.memoryTypeCount; ++i) {
      if (!(type_bits & (1u << i))) continue;
      if ((ctx.memory.memoryTypes[i].propertyFlags & want) == want) return i;
    }
  }
  return deviceError("no memory type fits: VK_ERROR_OUT_OF_DEVICE_MEMORY");
}

Result<uint32_t> memoryTypeFor(const VulkanContext& ctx, uint32_t type_bits, MemoryUse use) {
  return use == MemoryUse::Host
             ? findMemoryType(
                   ctx, type_bits,
                   VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, 0)
             : findMemoryType(ctx, type_bits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
}

Result<VkDeviceMemory> allocate(const VulkanContext& ctx, VkDeviceSize size, uint32_t type,
                                bool device_address) {
  VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.pNext = device_address ? &flags : nullptr;
  info.allocationSize = size;
  info.memoryTypeIndex = type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(vkCall("vkAllocateMemory",
                          [&] { return vkAllocateMemory(ctx.device, &info, nullptr, &memory); }));
  return memory;
}

// A case's buffers share a few blocks of this size: NVIDIA's driver spends
// about 1.3 ms freeing each VkDeviceMemory (10 of an H100 suite run's 38 s of
// case time went to freeing one allocation per buffer). A buffer larger than a
// quarter block gets a block of its own size.
constexpr VkDeviceSize kBlockBytes = VkDeviceSize(4) << 20;
// Every buffer starts on this boundary, beyond what its requirements ask:
// acceleration structures, scratch and shader binding tables want their
// device addresses aligned (at most 256 bytes on the devices we know).
constexpr VkDeviceSize kPlacementAlignment = 256;

// A new block of `type` for at least `bytes`, its free added to the case's
// Cleanup; mapped when the type is host-visible.
Result<MemoryBlock*> newBlock(const VulkanContext& ctx, uint32_t type, VkDeviceSize bytes,
                              Cleanup& cleanup) {
  MemoryBlock block;
  block.type = type;
  block.size = std::max(bytes, kBlockBytes);
  RAYSPEC_TRY(block.memory, allocate(ctx, block.size, type, true));
  VkDevice device = ctx.device;
  VkDeviceMemory memory = block.memory;
  cleanup.add([device, memory] { vkFreeMemory(device, memory, nullptr); });
  if (ctx.memory.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
    RAYSPEC_TRY_VOID(vkCheck(vkMapMemory(device, block.memory, 0, VK_WHOLE_SIZE, 0, &block.mapped),
                             "vkMapMemory"));
  cleanup.blocks().push_back(block);
  return &cleanup.blocks().back();
}

struct Placement {
  VkDeviceMemory memory;
  VkDeviceSize offset;
  void* mapped;
};

// Where a buffer with these requirements goes: the first of the case's blocks
// of its memory type with room, else a new block.
Result<Placement> place(const VulkanContext& ctx, const VkMemoryRequirements& req, MemoryUse use,
                        Cleanup& cleanup) {
  RAYSPEC_TRY(const uint32_t type, memoryTypeFor(ctx, req.memoryTypeBits, use));
  const VkDeviceSize alignment = std::max<VkDeviceSize>(req.alignment, kPlacementAlignment);
  MemoryBlock* chosen = nullptr;
  if (req.size <= kBlockBytes / 4)
    for (MemoryBlock& b : cleanup.blocks())
      if (b.type == type && alignUp(b.used, alignment) + req.size <= b.size) {
        chosen = &b;
        break;
      }
  if (!chosen) {
    RAYSPEC_TRY(chosen, newBlock(ctx, type, req.size, cleanup));
  }
  const VkDeviceSize offset = alignUp(chosen->used, alignment);
  chosen->used = offset + req.size;
  void* mapped = chosen->mapped ? static_cast<uint8_t*>(chosen->mapped) + offset : nullptr;
  return Placement{chosen->memory, offset, mapped};
}

// Memory of its own for an image with these requirements.
Result<VkDeviceMemory> imageMemory(const VulkanContext& ctx, const VkMemoryRequirements& req) {
  RAYSPEC_TRY(const uint32_t type, memoryTypeFor(ctx, req.memoryTypeBits, MemoryUse::Device));
  return allocate(ctx, req.size, type, false);
}

}  // namespace

Result<Buffer> createBuffer(const VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                            MemoryUse use, Cleanup& cleanup) {
  Buffer b;
  b.size = size;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size < 16 ? 16 : size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkDevice device = ctx.device;
  RAYSPEC_TRY_VOID(vkCheck(vkCreateBuffer(device, &info, nullptr, &b.buffer), "vkCreateBuffer"));
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(device, b.buffer, &req);
  // The buffer joins the Cleanup only after its block (which is freed after
  // it): until then it is destroyed here when no block can be had.
  const Result<Placement> at = place(ctx, req, use, cleanup);
  if (!at) {
    vkDestroyBuffer(device, b.buffer, nullptr);
    return at.error();
  }
  VkBuffer buffer = b.buffer;  // destroyed before the block it is placed in is freed
  cleanup.add([device, buffer] { vkDestroyBuffer(device, buffer, nullptr); });
  b.memory = at->memory;
  RAYSPEC_TRY_VOID(
      vkCheck(vkBindBufferMemory(device, b.buffer, at->memory, at->offset), "vkBindBufferMemory"));
  if (use == MemoryUse::Host) b.mapped = at->mapped;
  if (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT)
    b.address = bufferAddress(device, b.buffer);
  return b;
}

VkDeviceAddress bufferAddress(VkDevice device, VkBuffer buffer) {
  VkBufferDeviceAddressInfo ai{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
  ai.buffer = buffer;
  return vkGetBufferDeviceAddress(device, &ai);
}

Result<VkDeviceMemory> allocateMemory(const VulkanContext& ctx, VkDeviceSize size,
                                      uint32_t type_bits, MemoryUse use) {
  RAYSPEC_TRY(const uint32_t type, memoryTypeFor(ctx, type_bits, use));
  return allocate(ctx, size, type, true);
}

Result<Buffer> createUploadBuffer(const VulkanContext& ctx, const void* data, VkDeviceSize bytes,
                                  VkBufferUsageFlags usage, Cleanup& cleanup) {
  RAYSPEC_TRY(Buffer b, createBuffer(ctx, bytes, usage, MemoryUse::Host, cleanup));
  if (bytes) std::memcpy(b.mapped, data, bytes);
  return b;
}

Result<StorageImage> createStorageImage(const VulkanContext& ctx, uint32_t width, uint32_t height,
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
  RAYSPEC_TRY_VOID(vkCheck(vkCreateImage(device, &info, nullptr, &img.image), "vkCreateImage"));
  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(device, img.image, &req);
  // The image joins the Cleanup with its memory: until then it is destroyed
  // here when no memory can be had.
  const Result<VkDeviceMemory> memory_of = imageMemory(ctx, req);
  if (!memory_of) {
    vkDestroyImage(device, img.image, nullptr);
    return memory_of.error();
  }
  img.memory = *memory_of;
  VkImage image = img.image;
  VkDeviceMemory memory = img.memory;
  cleanup.add([device, image, memory] {
    vkDestroyImage(device, image, nullptr);
    vkFreeMemory(device, memory, nullptr);
  });
  RAYSPEC_TRY_VOID(
      vkCheck(vkBindImageMemory(device, img.image, img.memory, 0), "vkBindImageMemory"));

  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = img.image;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = format;
  view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  RAYSPEC_TRY_VOID(
      vkCheck(vkCreateImageView(device, &view, nullptr, &img.view), "vkCreateImageView"));
  VkImageView v = img.view;
  cleanup.add([device, v] { vkDestroyImageView(device, v, nullptr); });
  return img;
}

}  // namespace rayspec
