// One command buffer's batch of acceleration structure builds: where each
// build's scratch lies in one shared scratch buffer (each region guarded,
// R-AS-MEMORY), and the builds of one level recorded directly or indirectly,
// all in one command or one by one.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/memory_guards.h"

namespace rayspec {

// Acceleration structure writes -> reads by dst_stage.
void recordStructureBarrier(VkCommandBuffer cmd, VkPipelineStageFlags dst_stage);

// The builds of one command buffer and their places in one scratch buffer,
// each region followed by room for its guard (R-AS-MEMORY).
struct ScratchPlan {
  VkDeviceSize align = 0;
  VkDeviceSize total = 0;
  bool shared = false;  // scene.build.one_by_one: every build at offset 0, one after another
  bool sparse = false;  // scene.build.sparse: the buffer in sparse-bound memory
  struct Region {
    VkDeviceSize offset, size;
    std::string what;
  };
  std::vector<Region> regions;  // not shared: each build's; shared: the largest
  // A region of `size` bytes (`what` names it for its guard): its offset.
  VkDeviceSize add(VkDeviceSize size, const std::string& what);
};

// One scratch buffer for every build; its address aligned up to the
// scratch alignment, each region's guard added. Returns that aligned address.
Result<VkDeviceAddress> createScratch(const VulkanContext& ctx, const ScratchPlan& scratch,
                                      MemoryGuards& guards, Cleanup& cleanup);

// Builds (or updates) of one level recorded in one vkCmdBuildAccelerationStructuresKHR
// (or one each: scene.build.one_by_one), each with its scratch offset, and
// each structure's size and build and update scratch sizes.
struct Builds {
  std::vector<VkAccelerationStructureBuildGeometryInfoKHR> infos;
  std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> ranges;
  std::vector<VkDeviceSize> scratch_offsets, update_scratch, build_scratch;
  std::vector<VkDeviceSize> sizes;  // each structure's accelerationStructureSize
  // Each destination's room for a build: the size it was created with; 0 for
  // a compacted copy, which has room to be updated only.
  std::vector<VkDeviceSize> room;
  std::vector<size_t> blas;        // BLAS builds: the scene's BLAS index of each
  std::vector<std::string> names;  // "BLAS 2", "TLAS 0": what the guards call each
  // scene.build.command indirect: where the device reads each build's ranges
  // (vkCmdBuildAccelerationStructuresIndirectKHR), their stride, and each
  // build's most primitives per geometry (its ranges' counts).
  std::vector<VkDeviceAddress> indirect_ranges;
  std::vector<uint32_t> indirect_strides;
  std::vector<std::vector<uint32_t>> max_counts;
  std::vector<const uint32_t*> max_count_lists;

  void add(const VkAccelerationStructureBuildGeometryInfoKHR& info,
           const VkAccelerationStructureBuildRangeInfoKHR* range, VkDeviceSize scratch_offset);
  // Each build's scratch address: base plus its offset.
  void placeScratch(VkDeviceAddress base);
  // All in one command, or (one_by_one) each in its own, the scratch they
  // share written by one and then by the next behind a barrier; then the
  // structures' writes made visible to `next`.
  void record(const VulkanContext& ctx, VkCommandBuffer cmd, VkPipelineStageFlags next,
              bool one_by_one) const;
  // VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-10126: each build
  // (MODE_BUILD) writes a destination with room for its
  // accelerationStructureSize. Or the Harness error naming the first that
  // does not (a rayspec bug: the validation layer of 1.3.239 misses it).
  Result<void> checkRoom() const;
  // scene.build.command indirect: every build's ranges copied into one
  // buffer the device reads them from.
  Result<void> placeRangesForIndirect(const VulkanContext& ctx, Cleanup& cleanup);

 private:
  // Builds [first, first + count) in one command, direct or indirect.
  void recordBuilds(const VulkanContext& ctx, VkCommandBuffer cmd, size_t first,
                    size_t count) const;
};

// The same builds in UPDATE mode (R-AS-UPDATE): each structure updated in
// place from `geometries[i]` (which must outlive the result).
// rebuild (scene.build.tlas_update rebuild, top levels only): built anew
// from the new state's inputs instead (MODE_BUILD, no source).
Builds updatesOf(
    const Builds& built,
    const std::vector<const std::vector<VkAccelerationStructureGeometryKHR>*>& geometries,
    const std::vector<const VkAccelerationStructureBuildRangeInfoKHR*>& ranges,
    ScratchPlan& scratch, bool rebuild = false);

}  // namespace rayspec
