// The small allocator of the backend: a case's buffers placed one after
// another in a few memory blocks of the case (Cleanup::blocks), an image in a
// VkDeviceMemory of its own; all of it freed through the case's Cleanup.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

#include "base/align.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"

namespace rayspec {

enum class MemoryUse {
  Host,    // HOST_VISIBLE | HOST_COHERENT, persistently mapped
  Device,  // DEVICE_LOCAL when the device has it, else any type that fits
};

struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;  // the case's block it is placed in, shared
  VkDeviceSize size = 0;                   // as asked for (the buffer is at least 16 bytes)
  VkDeviceAddress address = 0;             // when usage has SHADER_DEVICE_ADDRESS
  void* mapped = nullptr;                  // MemoryUse::Host
};

// A zero size gives a 16-byte buffer (Vulkan forbids empty buffers).
// Each returns the Device error of the call that failed; what was made before
// it is in the Cleanup.
Result<Buffer> createBuffer(const VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                            MemoryUse use, Cleanup& cleanup);
// Host buffer holding a copy of data[0..bytes).
Result<Buffer> createUploadBuffer(const VulkanContext& ctx, const void* data, VkDeviceSize bytes,
                                  VkBufferUsageFlags usage, Cleanup& cleanup);

// A VkDeviceMemory of its own for `size` bytes: a type in type_bits that fits
// `use`, allocated with DEVICE_ADDRESS; the caller frees it.
Result<VkDeviceMemory> allocateMemory(const VulkanContext& ctx, VkDeviceSize size,
                                      uint32_t type_bits, MemoryUse use);
// The device address of a buffer made with SHADER_DEVICE_ADDRESS usage.
VkDeviceAddress bufferAddress(VkDevice device, VkBuffer buffer);

struct StorageImage {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
};

// 2D, optimal tiling, usage STORAGE | TRANSFER_SRC | TRANSFER_DST, layout UNDEFINED.
Result<StorageImage> createStorageImage(const VulkanContext& ctx, uint32_t width, uint32_t height,
                                        VkFormat format, Cleanup& cleanup);

}  // namespace rayspec
