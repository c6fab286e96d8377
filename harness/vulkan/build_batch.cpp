#include "vulkan/build_batch.h"

#include <algorithm>

#include "base/align.h"
#include "vulkan/build_log.h"
#include "vulkan/commands.h"
#include "vulkan/memory.h"
#include "vulkan/sparse_buffer.h"

namespace rayspec {
namespace {

// Between two builds sharing scratch memory: the first's scratch writes
// before the next one's reads and writes (scratch is accessed as
// ACCELERATION_STRUCTURE_READ/WRITE at the build stage).
void recordScratchBarrier(VkCommandBuffer cmd) {
  recordMemoryBarrier(cmd, {kBuildStage, VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR},
                      {kBuildStage, VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                                        VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR});
}

}  // namespace

void recordStructureBarrier(VkCommandBuffer cmd, VkPipelineStageFlags dst_stage) {
  recordMemoryBarrier(cmd, {kBuildStage, VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR},
                      {dst_stage, VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR});
}

VkDeviceSize ScratchPlan::add(VkDeviceSize size, const std::string& what) {
  if (shared) {
    if (regions.empty() || size > regions.front().size) regions = {{0, size, what}};
    total = std::max(total, guardedSize(size));
    return 0;
  }
  total = alignUp(total, align);
  const VkDeviceSize at = total;
  regions.push_back({at, size, what});
  total += guardedSize(size);
  return at;
}

Result<VkDeviceAddress> createScratch(const VulkanContext& ctx, const ScratchPlan& scratch,
                                      MemoryGuards& guards, Cleanup& cleanup) {
  constexpr VkBufferUsageFlags usage =
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
      VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  const VkDeviceSize size = scratch.total + scratch.align;
  Buffer buffer;
  if (scratch.sparse) {
    RAYSPEC_TRY(const SparseBuffer sparse, createSparseBuffer(ctx, size, usage, 0, cleanup));
    buffer = sparse.buffer;
  } else {
    RAYSPEC_TRY(buffer, createBuffer(ctx, size, usage, MemoryUse::Device, cleanup));
  }
  const VkDeviceAddress base = alignUp(buffer.address, scratch.align);
  for (const ScratchPlan::Region& r : scratch.regions)
    guards.add(buffer.buffer, base - buffer.address + r.offset, r.size, r.what);
  return base;
}

void Builds::add(const VkAccelerationStructureBuildGeometryInfoKHR& info,
                 const VkAccelerationStructureBuildRangeInfoKHR* range,
                 VkDeviceSize scratch_offset) {
  infos.push_back(info);
  ranges.push_back(range);
  scratch_offsets.push_back(scratch_offset);
}

void Builds::placeScratch(VkDeviceAddress base) {
  for (size_t i = 0; i < infos.size(); ++i)
    infos[i].scratchData.deviceAddress = base + scratch_offsets[i];
}

void Builds::record(const VulkanContext& ctx, VkCommandBuffer cmd, VkPipelineStageFlags next,
                    bool one_by_one) const {
  if (infos.empty()) return;
  if (!one_by_one) {
    recordBuilds(ctx, cmd, 0, infos.size());
  } else {
    for (size_t i = 0; i < infos.size(); ++i) {
      recordScratchBarrier(cmd);  // after the build before it, of this level or another
      recordBuilds(ctx, cmd, i, 1);
    }
  }
  recordStructureBarrier(cmd, next);
}

void Builds::recordBuilds(const VulkanContext& ctx, VkCommandBuffer cmd, size_t first,
                          size_t count) const {
  const uint32_t n = static_cast<uint32_t>(count);
  if (BuildLog* log = buildLog())
    for (size_t i = first; i < first + count; ++i)
      log->builds.push_back({infos[i].dstAccelerationStructure, infos[i].type});
  if (indirect_ranges.empty())
    ctx.fn.cmdBuildAccelerationStructures(cmd, n, &infos[first], &ranges[first]);
  else
    ctx.fn.cmdBuildAccelerationStructuresIndirect(cmd, n, &infos[first], &indirect_ranges[first],
                                                  &indirect_strides[first],
                                                  &max_count_lists[first]);
}

Result<void> Builds::placeRangesForIndirect(const VulkanContext& ctx, Cleanup& cleanup) {
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> all;
  std::vector<size_t> starts;
  max_counts.assign(infos.size(), {});
  for (size_t i = 0; i < infos.size(); ++i) {
    starts.push_back(all.size());
    for (uint32_t g = 0; g < infos[i].geometryCount; ++g) {
      all.push_back(ranges[i][g]);
      max_counts[i].push_back(ranges[i][g].primitiveCount);
    }
  }
  if (infos.empty()) return {};
  constexpr VkDeviceSize kRange = sizeof(VkAccelerationStructureBuildRangeInfoKHR);
  RAYSPEC_TRY(const Buffer buffer, createUploadBuffer(ctx, all.data(), all.size() * kRange,
                                                      VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                                          VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                                      cleanup));
  for (size_t i = 0; i < infos.size(); ++i) {
    indirect_ranges.push_back(buffer.address + starts[i] * kRange);
    indirect_strides.push_back(static_cast<uint32_t>(kRange));
    max_count_lists.push_back(max_counts[i].data());
  }
  return {};
}

Result<void> Builds::checkRoom() const {
  for (size_t i = 0; i < infos.size(); ++i) {
    if (infos[i].mode != VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR || room[i] >= sizes[i])
      continue;
    return errorOf(ErrorKind::Harness,
                   "a build of " + names[i] + " into a structure with room for " +
                       (room[i] ? std::to_string(room[i]) + " bytes"
                                : std::string("an update only (a compacted copy)")) +
                       ", less than its accelerationStructureSize " + std::to_string(sizes[i]) +
                       " (VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-10126): a rayspec bug");
  }
  return {};
}

Builds updatesOf(
    const Builds& built,
    const std::vector<const std::vector<VkAccelerationStructureGeometryKHR>*>& geometries,
    const std::vector<const VkAccelerationStructureBuildRangeInfoKHR*>& ranges,
    ScratchPlan& scratch, bool rebuild) {
  Builds out;
  for (size_t i = 0; i < built.infos.size(); ++i) {
    VkAccelerationStructureBuildGeometryInfoKHR info = built.infos[i];
    info.mode = rebuild ? VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR
                        : VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR;
    info.srcAccelerationStructure = rebuild ? VK_NULL_HANDLE : info.dstAccelerationStructure;
    info.pGeometries = geometries[i]->data();
    const std::string what = (rebuild ? "the rebuild scratch of " : "the update scratch of ") +
                             built.names[i] +
                             (rebuild ? " (buildScratchSize " : " (updateScratchSize ");
    const VkDeviceSize size = rebuild ? built.build_scratch[i] : built.update_scratch[i];
    out.add(info, ranges[i], scratch.add(size, what + std::to_string(size) + " bytes)"));
    out.names.push_back(built.names[i]);
    out.sizes.push_back(built.sizes[i]);
    out.room.push_back(built.room[i]);
  }
  return out;
}

}  // namespace rayspec
