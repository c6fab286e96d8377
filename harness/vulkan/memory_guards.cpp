#include "vulkan/memory_guards.h"

#include <cstring>

#include "base/align.h"
#include "vulkan/commands.h"
#include "vulkan/memory.h"

namespace rayspec {

VkDeviceSize guardOffset(VkDeviceSize offset, VkDeviceSize size) {
  return alignUp(offset + size, 4);
}

VkDeviceSize guardedSize(VkDeviceSize size) {
  return guardOffset(0, size) + kGuardBytes;
}

void MemoryGuards::add(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize size, std::string what) {
  guards_.push_back({buffer, guardOffset(offset, size), std::move(what)});
}

void MemoryGuards::recordFill(VkCommandBuffer cmd) {
  if (filled_ == guards_.size()) return;
  for (; filled_ < guards_.size(); ++filled_)
    vkCmdFillBuffer(cmd, guards_[filled_].buffer, guards_[filled_].offset, kGuardBytes,
                    kGuardPattern);
  recordMemoryBarrier(cmd, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                      {kBuildStage, VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                                        VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR});
}

void MemoryGuards::recordOverrun(VkCommandBuffer cmd) const {
  if (guards_.empty()) return;
  recordMemoryBarrier(cmd, {kBuildStage, VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR},
                      {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
  vkCmdFillBuffer(cmd, guards_.front().buffer, guards_.front().offset, 4, 0);
}

namespace {

// How many of a guard's bytes differ from the pattern, and the first that does.
struct GuardChange {
  size_t differ = 0, first = kGuardBytes;
};

GuardChange compareGuard(const uint8_t* bytes) {
  uint8_t pattern[4];
  std::memcpy(pattern, &kGuardPattern, 4);
  GuardChange c;
  for (size_t b = 0; b < kGuardBytes; ++b) {
    if (bytes[b] == pattern[b % 4]) continue;
    ++c.differ;
    if (c.first == kGuardBytes) c.first = b;
  }
  return c;
}

}  // namespace

Result<std::vector<std::string>> MemoryGuards::check(const VulkanContext& ctx, Cleanup& cleanup,
                                                     const std::string& when) {
  std::vector<std::string> changed;
  if (filled_ == 0) return changed;
  RAYSPEC_TRY(const Buffer back,
              createBuffer(ctx, filled_ * kGuardBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           MemoryUse::Host, cleanup));
  RAYSPEC_TRY(const VkCommandBuffer cmd, beginCommands(ctx, cleanup));
  recordMemoryBarrier(cmd, {VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT},
                      {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT});
  for (size_t i = 0; i < filled_; ++i) {
    const VkBufferCopy region{guards_[i].offset, i * kGuardBytes, kGuardBytes};
    vkCmdCopyBuffer(cmd, guards_[i].buffer, back.buffer, 1, &region);
  }
  recordMemoryBarrier(cmd, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                      {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
  RAYSPEC_TRY_VOID(submitAndWait(ctx, cmd));
  const auto* bytes = static_cast<const uint8_t*>(back.mapped);
  for (size_t i = 0; i < filled_; ++i) {
    const GuardChange c = compareGuard(bytes + i * kGuardBytes);
    if (!c.differ || guards_[i].reported) continue;
    guards_[i].reported = true;
    changed.push_back(guards_[i].what + ": " + std::to_string(c.differ) + " of the " +
                      std::to_string(kGuardBytes) + " guard bytes after it changed" +
                      (when.empty() ? "" : " " + when) + " (the first at guard byte " +
                      std::to_string(c.first) + "): written past the size the device reported");
  }
  return changed;
}

}  // namespace rayspec
