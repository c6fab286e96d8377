#include "vulkan/structure_arena.h"

#include <algorithm>

#include "base/align.h"
#include "vulkan/acceleration_structure.h"
#include "vulkan/commands.h"
#include "vulkan/memory_guards.h"

namespace rayspec {

Result<SparseBuffer> StructureArena::place(const VulkanContext& ctx, VkDeviceSize size,
                                           VkAccelerationStructureTypeKHR type) {
  const VkDeviceSize room = guardedSize(size);
  while (current_ < chunks_.size() &&
         alignUp(chunks_[current_].used, kStructureOffsetAlign) + room >
             chunks_[current_].buffer.size)
    ++current_;
  if (current_ == chunks_.size()) {
    constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                                         VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                                         VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                         VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    Chunk chunk;
    RAYSPEC_TRY(chunk.buffer, createBuffer(ctx, std::max(kArenaBufferBytes, room), usage,
                                           MemoryUse::Device, cleanup_));
    chunks_.push_back(chunk);
  }
  Chunk& chunk = chunks_[current_];
  SparseBuffer out;
  out.buffer = chunk.buffer;
  out.offset = alignUp(chunk.used, kStructureOffsetAlign);
  chunk.used = out.offset + room;
  places_.push_back({chunk.buffer.buffer, out.offset, size, type});
  return out;
}

Scene decoyScene(const Scene& scene) {
  Scene d = scene.earlier.empty() ? scene : *scene.earlier.front();
  d.earlier.clear();
  d.build.copy = AsCopy::None;
  d.build.updates_before_copy.reset();
  d.build.update_into_other = false;
  constexpr float kAway = 1000;
  for (Blas& b : d.blases)
    for (Geometry& g : b.geometries) {
      if (g.written.empty())  // a format that rounds positions keeps them
        for (Vec3& v : g.vertices) v[0] += kAway;
      for (auto& box : g.aabbs) {
        box[0] += kAway;
        box[3] += kAway;
      }
    }
  return d;
}

void StructureArena::rewind() {
  for (Chunk& c : chunks_) c.used = 0;
  current_ = 0;
  places_.clear();
}

Result<void> createOverlays(const VulkanContext& ctx, const StructureArena& arena,
                            LayoutFault fault, Cleanup& cleanup) {
  const bool clears = fault == LayoutFault::CreationClears;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  if (clears) {
    RAYSPEC_TRY(cmd, beginCommands(ctx, cleanup));
  }
  for (const ArenaPlace& p : arena.places()) {
    VkAccelerationStructureCreateInfoKHR info{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
    info.buffer = p.buffer;
    info.offset = p.offset;
    info.size = p.size;
    info.type = p.type;
    RAYSPEC_TRY_VOID(createStructureOver(ctx, info, p.type, 0, cleanup));
    if (clears) vkCmdFillBuffer(cmd, p.buffer, p.offset, alignUp(p.size, 4), 0);
  }
  if (clears) RAYSPEC_TRY_VOID(submitAndWait(ctx, cmd));
  return {};
}

}  // namespace rayspec
