// scene.build.storage shared and reused: a scene's acceleration structures
// placed one after another in a few large buffers instead of a buffer each,
// as the CTS's BLAS pools put them (ray_tracing misc reuse_scratch_buffer)
// and as its reuse_creation_buffer_{top,bottom} reuse one buffer. Each place
// starts at a multiple of 256 bytes
// (VUID-VkAccelerationStructureCreateInfoKHR-offset-03734) and leaves room
// for the guard after the structure (R-AS-MEMORY), so a build that writes
// past its size reaches the guard before the next structure.
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include "base/result.h"
#include "case/case.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/memory.h"
#include "vulkan/sparse_buffer.h"
#include "vulkan/vk_fault_hook.h"

namespace rayspec {

// The bytes of one buffer of the arena, unless a structure needs more.
constexpr VkDeviceSize kArenaBufferBytes = VkDeviceSize{1} << 20;
// A structure's offset in its buffer is a multiple of this.
constexpr VkDeviceSize kStructureOffsetAlign = 256;

// One structure's place, as the arena handed it out.
struct ArenaPlace {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize offset = 0, size = 0;
  VkAccelerationStructureTypeKHR type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
};

class StructureArena {
 public:
  // The arena's buffers are destroyed by `cleanup` (the case's: they
  // outlive the structures of a decoy built in them).
  explicit StructureArena(Cleanup& cleanup) : cleanup_(cleanup) {}
  // Room for `size` bytes and their guard, for a structure created as
  // `type`: after the places before it in the newest buffer where it fits,
  // else at the start of a new buffer (of kArenaBufferBytes, or the room it
  // needs). The buffer (offset, page 0) as vulkan/acceleration_structure.cpp
  // creates a structure in.
  Result<SparseBuffer> place(const VulkanContext& ctx, VkDeviceSize size,
                             VkAccelerationStructureTypeKHR type);
  // The places handed out from now on start over at the first buffer's
  // start (the structures in them destroyed), and the list of places too.
  void rewind();
  // Every place handed out since the last rewind, in order.
  const std::vector<ArenaPlace>& places() const { return places_; }

 private:
  struct Chunk {
    Buffer buffer;
    VkDeviceSize used = 0;
  };
  Cleanup& cleanup_;
  std::vector<Chunk> chunks_;
  size_t current_ = 0;
  std::vector<ArenaPlace> places_;
};

// R-AS-CREATE (scene.build.storage reused; reuse_creation_buffer): another
// structure created over each of the arena's places, at its offset and size,
// kept until cleanup and never built. `fault` CreationClears (the planted
// fault creation-clears-memory): each such creation zeroes the memory, as a
// driver whose vkCreateAccelerationStructureKHR wrote it would.
Result<void> createOverlays(const VulkanContext& ctx, const StructureArena& arena,
                            LayoutFault fault, Cleanup& cleanup);

// What scene.build.storage reused builds first and destroys: the scene as
// first built (no update, no copy), every box and every float vertex moved
// 1000 along x (a NaN stays NaN, so the same primitives are inactive; a
// format that rounds positions keeps them), so that a device that still
// traced any of it would show it.
Scene decoyScene(const Scene& scene);

}  // namespace rayspec
