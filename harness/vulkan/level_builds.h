// The builds of each level of a scene (vulkan/scene_builder.cpp runs them):
// the BLAS and TLAS structures created at the sizes the driver asks for,
// their scratch placed; the instances as the device reads them; updates
// written into other structures (scene.build.update_into other).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "case/case.h"
#include "vulkan/acceleration_structure.h"
#include "vulkan/build_batch.h"
#include "vulkan/build_layout.h"
#include "vulkan/built_structure.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/memory_guards.h"

namespace rayspec {

// One BLAS build: its geometry, ranges and input offsets (describeBlas,
// vulkan/scene_builder.cpp), then its structure.
struct BlasBuild {
  std::vector<VkAccelerationStructureGeometryKHR> geometries;
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges;
  std::vector<uint32_t> max_primitives;
  std::vector<uint64_t> offsets;  // per geometry: data, index, transform (packer offsets)
  VkAccelerationStructureKHR handle = VK_NULL_HANDLE;
  VkDeviceAddress address = 0;
  VkDeviceSize size = 0;  // accelerationStructureSize
};

// The BLAS builds: their structures created at the sizes the driver asks
// for, their scratch placed. Only BLASes some instance reaches are built.
Result<Builds> createBlases(const VulkanContext& ctx, std::vector<BlasBuild>& builds,
                            const std::vector<bool>& used,
                            VkBuildAccelerationStructureFlagsKHR flags,
                            const StructureMaking& making, ScratchPlan& scratch,
                            MemoryGuards& guards, Cleanup& cleanup);

// The instances of every top level, one level after the other.
std::vector<VkAccelerationStructureInstanceKHR> allInstances(const Scene& scene,
                                                             const std::vector<BlasBuild>& builds);

// The instance geometry of each level over an instance buffer laid out as
// `layout` says.
std::vector<std::vector<VkAccelerationStructureGeometryKHR>> instanceGeometry(
    VkDeviceAddress instances, const InstanceLayout& layout, uint32_t levels);

// The TLAS builds over `geometry` (one a level): structures created, scratch placed.
Result<Builds> createTlases(
    const VulkanContext& ctx,
    const std::vector<std::vector<VkAccelerationStructureGeometryKHR>>& geometry,
    uint32_t instance_count, const std::vector<VkAccelerationStructureBuildRangeInfoKHR>& ranges,
    VkBuildAccelerationStructureFlagsKHR flags, const StructureMaking& making, ScratchPlan& scratch,
    std::vector<BuiltStructure>& structures, MemoryGuards& guards, Cleanup& cleanup);

// scene.build.update_into other: each update reads the structure the one
// before wrote and writes a new one of the same size (source and destination
// differ); returns the structures the last update wrote, which the traces use.
Result<std::vector<VkAccelerationStructureKHR>> updateIntoOthers(
    const VulkanContext& ctx, std::vector<Builds>& updates, const Builds& built,
    VkAccelerationStructureTypeKHR type, const StructureMaking& making, MemoryGuards& guards,
    Cleanup& cleanup);

}  // namespace rayspec
