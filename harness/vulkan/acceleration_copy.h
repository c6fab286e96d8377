// Copies of acceleration structures (scene.build.copy, R-AS-COPY): clones at
// the size they were created with, or compacted copies at the size the
// device reports after the build (a query pool of
// VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR), or serialized
// to host-visible memory and deserialized into new structures (the data's
// header checked: compatible with the device, the sizes it reported). Each
// step is a submission of its own, waited on.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "case/case.h"
#include "vulkan/acceleration_structure.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/memory_guards.h"

namespace rayspec {

// The copies of `from` (all of level `type`, built and complete; each copy
// created as `making` says), in order, made by
// vkCmdCopyAccelerationStructureKHR in `mode` (Clone or Compact), or through
// memory (Serialize), readable by
// builds and ray tracing shaders once this returns; each copy keeps its
// source's name. Each copy, and each structure's serialized bytes, guarded
// after the size the device reported for it (R-AS-MEMORY; the guards are
// filled here, checked by the caller).
// Or the Device error.
Result<std::vector<BuiltStructure>> copyStructures(const VulkanContext& ctx,
                                                   const std::vector<BuiltStructure>& from,
                                                   VkAccelerationStructureTypeKHR type,
                                                   const StructureMaking& making, AsCopy mode,
                                                   MemoryGuards& guards, Cleanup& cleanup);

}  // namespace rayspec
