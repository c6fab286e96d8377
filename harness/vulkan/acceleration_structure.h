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

// Builds the scene and returns its top levels, ready for ray tracing
// shaders: one BLAS build per case Blas that some instance references (all
// in one vkCmdBuildAccelerationStructuresKHR), a barrier, the TLAS builds (an
// instance with a null BLAS gets accelerationStructureReference 0), with the
// flags of scene.build. One TLAS per top level (Scene::tlasCount()), each
// over all instances in order, those of the other levels with reference 0.
// One submission; with scene.build.copy (R-AS-COPY) the BLASes are copied
// before the TLASes are built over the copies, and the TLASes are copied in
// turn: the traces see only copies (but a top level rebuilt after a copy
// too small for a build, which is rebuilt into a structure of its build
// size: tlas_update rebuild after a compact copy). extra_flags join scene.build's flags on
// every build (ALLOW_DATA_ACCESS where a stage fetches vertex positions).
// Each top level comes with the size it was created with. Buffers and
// structures live until cleanup runs. Every structure, scratch region and
// serialized copy is guarded (R-AS-MEMORY): each guard the commands changed
// is a line of `overruns`, checked once each copy ended and once at the end.
// scene.build.storage shared: every structure placed in a StructureArena;
// reused: the decoy scene (structure_arena.h) built there first, waited on
// and destroyed, the scene built over its memory, then another structure
// created over each built one and kept, never built (R-AS-CREATE).
// scene.build.queries asks each level's structures before its copy (or after
// its last update), each broken guarantee a line of `query_findings`
// (vulkan/structure_queries.h).
// Or the Device error.
Result<std::vector<BuiltStructure>> buildScene(const VulkanContext& ctx, const Scene& scene,
                                               VkBuildAccelerationStructureFlagsKHR extra_flags,
                                               Cleanup& cleanup, std::vector<std::string>& overruns,
                                               std::vector<DeviceFinding>& query_findings);

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
