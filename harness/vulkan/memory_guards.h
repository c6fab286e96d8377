// R-AS-MEMORY: a build, update or copy writes only inside the memory the
// device reported for it (accelerationStructureSize, buildScratchSize,
// updateScratchSize, the compacted or deserialized size). Each such region
// is followed by a guard of kGuardBytes holding a known pattern, written
// before the commands that could overrun it and read back after them; a
// guard that changed is a device finding naming the region and its size.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "base/result.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"

namespace rayspec {

constexpr VkDeviceSize kGuardBytes = 256;
constexpr uint32_t kGuardPattern = 0x5A17C0DEu;

// Room a buffer needs for `size` bytes and the guard after them.
VkDeviceSize guardedSize(VkDeviceSize size);
// Where the guard after `size` bytes at `offset` starts (4-byte aligned, as
// vkCmdFillBuffer wants).
VkDeviceSize guardOffset(VkDeviceSize offset, VkDeviceSize size);

// The guards of one scene's builds. The buffers must have TRANSFER_SRC and
// TRANSFER_DST usage.
class MemoryGuards {
 public:
  // A guard at guardOffset(offset, size) of buffer, after `what` (which names
  // the region and its reported size).
  void add(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize size, std::string what);
  // Fills the guards added since the last call, and orders the fills before
  // the acceleration structure commands that follow.
  void recordFill(VkCommandBuffer cmd);
  // Test only (fault build-writes-past-size): 4 bytes of the first guard
  // overwritten, as a build that ran past its size would.
  void recordOverrun(VkCommandBuffer cmd) const;
  // After every command that could write them ended: each guard filled so
  // far copied back and compared. One line per changed guard that no earlier
  // check reported, `when` (if any) saying which commands it follows ("after
  // the copy of the top levels"); none when all held.
  Result<std::vector<std::string>> check(const VulkanContext& ctx, Cleanup& cleanup,
                                         const std::string& when = "");

 private:
  struct Guard {
    VkBuffer buffer;
    VkDeviceSize offset;
    std::string what;
    bool reported = false;
  };
  std::vector<Guard> guards_;
  size_t filled_ = 0;
};

}  // namespace rayspec
