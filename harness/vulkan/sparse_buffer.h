// Buffers in sparse-bound memory (scene.build.sparse): created with
// VK_BUFFER_CREATE_SPARSE_BINDING_BIT and bound by one vkQueueBindSparse on
// the case's queue, page by page (a page: the buffer's memory alignment, the
// sparse block size). The pages are spread over two allocations, page i in
// allocation i % 2 and each allocation's pages in reverse order, so that no
// two neighbouring pages of the buffer are neighbours in memory. Needs
// sparseBinding and a queue with VK_QUEUE_SPARSE_BINDING_BIT
// (vulkan/case_support.h says NotSupported before a case gets here).
#pragma once

#include <vulkan/vulkan.h>

#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/memory.h"

namespace rayspec {

struct SparseBuffer {
  Buffer buffer;  // memory: VK_NULL_HANDLE (it lies in several), never mapped
  VkDeviceSize page = 0;
  VkDeviceSize offset = 0;  // where the `size` bytes asked for start
};

// Where a structure starts: 256 bytes before the first page boundary (a
// structure's offset must be a multiple of 256).
constexpr VkDeviceSize kBeforePageBoundary = 256;

// Where build inputs of `size` bytes start, so that they straddle the first
// page boundary: half of them before it (16-byte aligned, at least 16), at
// most kBeforePageBoundary.
VkDeviceSize straddlingStart(VkDeviceSize size);

// A sparse buffer with room for `size` bytes at its `offset`, bound and
// ready once this returns (the queue waited on); buffer and memory destroyed
// by cleanup. before_boundary: the bytes start that many bytes before the
// first page boundary (0: at the buffer's start), so that any more lie on
// two pages or more.
Result<SparseBuffer> createSparseBuffer(const VulkanContext& ctx, VkDeviceSize size,
                                        VkBufferUsageFlags usage, VkDeviceSize before_boundary,
                                        Cleanup& cleanup);

// data[0..bytes) copied to the buffer's offset from a host buffer (the buffer
// needs TRANSFER_DST usage), submitted and waited on. lose_page (the planted
// fault sparse-page-lost): then the buffer's second page bound to a new
// allocation and zeroed there, as a driver that lost that page's binding
// would show it: the device reads zeros in place of those bytes.
Result<void> uploadToSparse(const VulkanContext& ctx, const SparseBuffer& to, const void* data,
                            VkDeviceSize bytes, bool lose_page, Cleanup& cleanup);

}  // namespace rayspec
