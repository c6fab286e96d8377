// Bottom- and top-level acceleration structures, built on the device through
// a command buffer (lavapipe has no host commands).
#pragma once

#include <vulkan/vulkan.h>

#include "case/case.h"
#include "results/results.h"
#include "vulkan/built_structure.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/memory_guards.h"

namespace rayspec {

// The VkFormat of a vertex format (R-VERTEX-FORMAT).
VkFormat vkVertexFormat(VertexFormat f);

// The device address of an acceleration structure (vkGetAccelerationStructureDeviceAddressKHR).
VkDeviceAddress structureAddress(const VulkanContext& ctx, VkAccelerationStructureKHR as);

// Every build's and update's flags: scene.build's, and ALLOW_COMPACTION where
// the structures are compacted or their compacted size is queried.
VkBuildAccelerationStructureFlagsKHR buildFlags(const AsBuild& build);

// Which of the scene's BLASes some instance references: only those are built.
std::vector<bool> reachedBlases(const Scene& scene);

class StructureArena;

// How a scene's structures are made (scene.build.generic, scene.build.sparse;
// in host-visible memory where the host queries them: scene.build.query_command
// host; arena: where scene.build.storage shared or reused places them, none:
// each in a buffer of its own).
struct StructureMaking {
  GenericLevels generic = GenericLevels::None;
  bool sparse = false;
  bool host_visible = false;
  StructureArena* arena = nullptr;
  static StructureMaking of(const AsBuild& build) {
    return {build.generic, build.sparse.structures, build.queries.command == QueryCommand::Host};
  }
  // The type a structure of level `level` (bottom or top) is created with:
  // GENERIC where scene.build.generic names its level.
  VkAccelerationStructureTypeKHR createdAs(VkAccelerationStructureTypeKHR level) const;
};

// The structure's storage buffer and the structure (size bytes), destroyed
// by cleanup; a guard after its size (R-AS-MEMORY), `what` naming the
// structure and which of its sizes the device reported. `level` is the type
// its builds name; it is created as `making` says: with the GENERIC type, or
// in a sparse buffer (vulkan/sparse_buffer.h), placed across a page boundary,
// or in the arena (vulkan/structure_arena.h).
Result<VkAccelerationStructureKHR> createStructure(const VulkanContext& ctx,
                                                   VkAccelerationStructureTypeKHR level,
                                                   const StructureMaking& making, VkDeviceSize size,
                                                   Cleanup& cleanup, MemoryGuards& guards,
                                                   const std::string& what);

// The structure `info` describes (its buffer, offset, size and created
// type), destroyed by cleanup; the build log (vulkan/build_log.h) notes it
// with `level`, the type its builds name, and `page`, its sparse buffer's
// page size (0: bound whole). Or the Device error.
Result<VkAccelerationStructureKHR> createStructureOver(
    const VulkanContext& ctx, const VkAccelerationStructureCreateInfoKHR& info,
    VkAccelerationStructureTypeKHR level, VkDeviceSize page, Cleanup& cleanup);

}  // namespace rayspec
