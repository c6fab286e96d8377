// A scene's acceleration structures built on the device, in the order
// scene.build asks (vulkan/level_builds.h: each level's builds).
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "case/case.h"
#include "results/results.h"
#include "vulkan/built_structure.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"

namespace rayspec {

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

}  // namespace rayspec
