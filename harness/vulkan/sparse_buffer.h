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

// Where contents that straddle the first page boundary start: 256 bytes
// before it (a structure's offset must be a multiple of 256).
constexpr VkDeviceSize kBeforePageBoundary = 256;

// A sparse buffer with room for `size` bytes at its `offset`, bound and
// ready once this returns (the queue waited on); buffer and memory destroyed
// by cleanup. across_page: the bytes start kBeforePageBoundary before the
// first page boundary, so that any more than that lie on two pages or more.
Result<SparseBuffer> createSparseBuffer(const VulkanContext& ctx, VkDeviceSize size,
                                        VkBufferUsageFlags usage, bool across_page,
                                        Cleanup& cleanup);

}  // namespace rayspec
