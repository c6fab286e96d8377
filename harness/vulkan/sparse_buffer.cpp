#include "vulkan/sparse_buffer.h"

#include <algorithm>
#include <vector>

#include "vulkan/build_log.h"
#include "vulkan/commands.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

// Page i of `pages` in allocation i % 2, each allocation's pages in
// reverse order.
std::vector<VkSparseMemoryBind> scatteredBinds(VkDeviceSize page, VkDeviceSize pages,
                                               const std::vector<VkDeviceMemory>& memory) {
  const VkDeviceSize per_allocation[2] = {(pages + 1) / 2, pages / 2};
  std::vector<VkSparseMemoryBind> binds;
  for (VkDeviceSize i = 0; i < pages; ++i) {
    VkSparseMemoryBind b{};
    b.resourceOffset = i * page;
    b.size = page;
    b.memory = memory[i % 2];
    b.memoryOffset = (per_allocation[i % 2] - 1 - i / 2) * page;
    binds.push_back(b);
  }
  return binds;
}

// The two allocations of a buffer of `pages` pages (one when it has one
// page), each freed by cleanup after the buffer is destroyed.
Result<std::vector<VkDeviceMemory>> allocatePages(const VulkanContext& ctx,
                                                  const VkMemoryRequirements& req,
                                                  VkDeviceSize pages, Cleanup& cleanup) {
  std::vector<VkDeviceMemory> memory;
  for (VkDeviceSize count : {(pages + 1) / 2, pages / 2}) {
    if (count == 0) continue;
    RAYSPEC_TRY(const VkDeviceMemory m,
                allocateMemory(ctx, count * req.alignment, req.memoryTypeBits, MemoryUse::Device));
    VkDevice device = ctx.device;
    cleanup.add([device, m] { vkFreeMemory(device, m, nullptr); });
    memory.push_back(m);
  }
  return memory;
}

// One vkQueueBindSparse of every page, waited on.
Result<void> bindPages(const VulkanContext& ctx, VkBuffer buffer,
                       const std::vector<VkSparseMemoryBind>& binds) {
  VkSparseBufferMemoryBindInfo buffer_binds{};
  buffer_binds.buffer = buffer;
  buffer_binds.bindCount = static_cast<uint32_t>(binds.size());
  buffer_binds.pBinds = binds.data();
  VkBindSparseInfo info{VK_STRUCTURE_TYPE_BIND_SPARSE_INFO};
  info.bufferBindCount = 1;
  info.pBufferBinds = &buffer_binds;
  RAYSPEC_TRY_VOID(vkCall("vkQueueBindSparse",
                          [&] { return vkQueueBindSparse(ctx.queue, 1, &info, VK_NULL_HANDLE); }));
  return vkCheck(vkQueueWaitIdle(ctx.queue), "vkQueueWaitIdle");
}

void logBinding(const VkBufferCreateInfo& info, const VkMemoryRequirements& req,
                const std::vector<VkSparseMemoryBind>& binds, size_t allocations) {
  BuildLog* log = buildLog();
  if (!log) return;
  LoggedSparseBuffer s;
  s.flags = info.flags;
  s.size = req.size;
  s.page = req.alignment;
  s.binds = static_cast<uint32_t>(binds.size());
  s.allocations = static_cast<uint32_t>(allocations);
  for (size_t i = 1; i < binds.size(); ++i)
    if (binds[i].memory != binds[i - 1].memory ||
        binds[i].memoryOffset != binds[i - 1].memoryOffset + binds[i - 1].size)
      s.in_order = false;
  log->sparse.push_back(s);
}

// The planted fault sparse-page-lost: the buffer's second page (if it has
// one) bound to an allocation of its own and zeroed through the buffer.
Result<void> losePage(const VulkanContext& ctx, const SparseBuffer& lost, Cleanup& cleanup) {
  const VkBuffer buffer = lost.buffer.buffer;
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(ctx.device, buffer, &req);
  const VkDeviceSize end = lost.offset + std::max<VkDeviceSize>(lost.buffer.size, 16);
  const VkDeviceSize zeroed = std::min(end - std::min(end, req.alignment), req.alignment) / 4 * 4;
  if (zeroed == 0) return {};
  RAYSPEC_TRY(const std::vector<VkDeviceMemory> memory, allocatePages(ctx, req, 1, cleanup));
  VkSparseMemoryBind bind{};
  bind.resourceOffset = req.alignment;
  bind.size = req.alignment;
  bind.memory = memory.front();
  RAYSPEC_TRY_VOID(bindPages(ctx, buffer, {bind}));
  RAYSPEC_TRY(VkCommandBuffer cmd, beginCommands(ctx, cleanup));
  vkCmdFillBuffer(cmd, buffer, req.alignment, zeroed, 0);
  return submitAndWait(ctx, cmd);
}

Result<VkBuffer> sparseBuffer(VkDevice device, const VkBufferCreateInfo& info) {
  VkBuffer buffer = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(vkCheck(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer"));
  return buffer;
}

}  // namespace

VkDeviceSize straddlingStart(VkDeviceSize size) {
  return std::clamp<VkDeviceSize>(size / 2 / 16 * 16, 16, kBeforePageBoundary);
}

Result<SparseBuffer> createSparseBuffer(const VulkanContext& ctx, VkDeviceSize size,
                                        VkBufferUsageFlags usage, VkDeviceSize before_boundary,
                                        Cleanup& cleanup) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.flags = VK_BUFFER_CREATE_SPARSE_BINDING_BIT;
  info.size = std::max<VkDeviceSize>(size, 16);
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  SparseBuffer out;
  VkDevice device = ctx.device;
  RAYSPEC_TRY(VkBuffer buffer, sparseBuffer(device, info));
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(device, buffer, &req);
  if (before_boundary && req.alignment > before_boundary) {  // made again, longer
    vkDestroyBuffer(device, buffer, nullptr);
    out.offset = req.alignment - before_boundary;
    info.size += out.offset;
    RAYSPEC_TRY(buffer, sparseBuffer(device, info));
    vkGetBufferMemoryRequirements(device, buffer, &req);
  }
  out.buffer.buffer = buffer;
  out.page = req.alignment;
  const VkDeviceSize pages = (req.size + req.alignment - 1) / req.alignment;
  // The buffer joins the Cleanup after its memory, so that it goes first.
  const Result<std::vector<VkDeviceMemory>> memory = allocatePages(ctx, req, pages, cleanup);
  if (!memory) {
    vkDestroyBuffer(device, buffer, nullptr);
    return memory.error();
  }
  cleanup.add([device, buffer] { vkDestroyBuffer(device, buffer, nullptr); });
  const std::vector<VkSparseMemoryBind> binds = scatteredBinds(req.alignment, pages, *memory);
  RAYSPEC_TRY_VOID(bindPages(ctx, buffer, binds));
  logBinding(info, req, binds, memory->size());
  out.buffer.size = size;
  if (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT)
    out.buffer.address = bufferAddress(device, buffer);
  return out;
}

Result<void> uploadToSparse(const VulkanContext& ctx, const SparseBuffer& to, const void* data,
                            VkDeviceSize bytes, bool lose_page, Cleanup& cleanup) {
  if (bytes) {
    RAYSPEC_TRY(const Buffer from,
                createUploadBuffer(ctx, data, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, cleanup));
    RAYSPEC_TRY(VkCommandBuffer cmd, beginCommands(ctx, cleanup));
    const VkBufferCopy region{0, to.offset, bytes};
    vkCmdCopyBuffer(cmd, from.buffer, to.buffer.buffer, 1, &region);
    RAYSPEC_TRY_VOID(submitAndWait(ctx, cmd));
  }
  return lose_page ? losePage(ctx, to, cleanup) : Result<void>{};
}

}  // namespace rayspec
