#include "vulkan/scene_builder.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "case/build_order.h"
#include "vulkan/acceleration_copy.h"
#include "vulkan/acceleration_structure.h"
#include "vulkan/build_batch.h"
#include "vulkan/build_layout.h"
#include "vulkan/commands.h"
#include "vulkan/level_builds.h"
#include "vulkan/memory.h"
#include "vulkan/sparse_buffer.h"
#include "vulkan/structure_arena.h"
#include "vulkan/structure_queries.h"
#include "vulkan/vk_fault_hook.h"

namespace rayspec {
namespace {

constexpr VkBufferUsageFlags kInputUsage =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

// Host bytes of every BLAS build input (vertices, indices, transforms, boxes),
// each piece at a 16-byte aligned offset, uploaded as one buffer.
class InputPacker {
 public:
  uint64_t add(const void* data, size_t bytes) {
    uint64_t at = (bytes_.size() + 15) / 16 * 16;
    bytes_.resize(at + bytes);
    if (bytes) std::memcpy(bytes_.data() + at, data, bytes);
    return at;
  }
  const std::vector<uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<uint8_t> bytes_;
};

constexpr uint64_t kNone = ~0ull;

// The copies that filled sparse input buffers (uploadToSparse, waited on)
// made visible to the builds that read them.
void recordUploadBarrier(VkCommandBuffer cmd) {
  recordMemoryBarrier(cmd, {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT},
                      {kBuildStage, VK_ACCESS_SHADER_READ_BIT});
}

// First pass: pack the inputs (laid out as scene.build asks, with the
// planted layout fault if any) and fill the geometry descriptions with
// packer offsets; addresses are patched once the input buffer exists.
void describeBlas(const Blas& blas, const AsBuild& layout, InputPacker& packer, BlasBuild& b) {
  const LayoutFault fault = injectedLayoutFault();
  auto place = [&packer](const std::vector<uint8_t>& bytes) {
    return bytes.empty() ? kNone : packer.add(bytes.data(), bytes.size());
  };
  for (const Geometry& g : blas.geometries) {
    VkAccelerationStructureGeometryKHR geo{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    geo.flags = g.flags;
    uint64_t data = kNone, index = kNone, transform = kNone;
    VkAccelerationStructureBuildRangeInfoKHR range{};
    if (g.kind == Geometry::Kind::Triangles) {
      const TriangleInputs in = layTriangles(g, layout, fault);
      geo.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
      auto& t = geo.geometry.triangles;
      t.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
      t.vertexFormat = vkVertexFormat(in.format);
      t.vertexStride = in.stride;
      t.maxVertex = in.max_vertex;
      t.indexType = g.indices.empty() ? VK_INDEX_TYPE_NONE_KHR
                    : g.index16       ? VK_INDEX_TYPE_UINT16
                                      : VK_INDEX_TYPE_UINT32;
      data = packer.add(in.vertices.data(), in.vertices.size());
      index = place(in.indices);
      transform = place(in.transform);
      range = in.range;
    } else {
      const AabbInputs in = layAabbs(g, layout, fault);
      geo.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
      auto& a = geo.geometry.aabbs;
      a.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
      a.stride = in.stride;
      data = packer.add(in.boxes.data(), in.boxes.size());
      range = in.range;
    }
    b.geometries.push_back(geo);
    b.offsets.insert(b.offsets.end(), {data, index, transform});
    b.ranges.push_back(range);
    b.max_primitives.push_back(range.primitiveCount);
  }
}

void patchAddresses(BlasBuild& b, VkDeviceAddress base) {
  for (size_t i = 0; i < b.geometries.size(); ++i) {
    auto at = [&](uint64_t off) {
      return off == kNone ? VkDeviceAddress(0) : base + off;
    };
    VkAccelerationStructureGeometryKHR& geo = b.geometries[i];
    if (geo.geometryType == VK_GEOMETRY_TYPE_TRIANGLES_KHR) {
      geo.geometry.triangles.vertexData.deviceAddress = at(b.offsets[3 * i]);
      geo.geometry.triangles.indexData.deviceAddress = at(b.offsets[3 * i + 1]);
      geo.geometry.triangles.transformData.deviceAddress = at(b.offsets[3 * i + 2]);
    } else {
      geo.geometry.aabbs.data.deviceAddress = at(b.offsets[3 * i]);
    }
  }
}

StructureMaking withArena(StructureMaking making, StructureArena* arena) {
  making.arena = arena;
  return making;
}

// The builds of one scene: BLASes, their updates and copy in the order of
// scene.build.order, then TLASes over the final BLASes, their updates and
// copy in the same order. Each state's instances (as first built, after each
// update) in a host-visible buffer, written once the BLASes are final.
class SceneBuilder {
 public:
  SceneBuilder(const VulkanContext& ctx, const Scene& scene,
               VkBuildAccelerationStructureFlagsKHR extra_flags, StructureArena* arena,
               Cleanup& cleanup)
      : ctx_(ctx),
        scene_(scene),
        flags_(buildFlags(scene.build) | extra_flags),
        making_(withArena(StructureMaking::of(scene.build), arena)),
        cleanup_(cleanup) {
    for (const auto& e : scene.earlier) states_.push_back(e.get());
    states_.push_back(&scene);
    scratch_.align = ctx.as_props.minAccelerationStructureScratchOffsetAlignment;
    scratch_.shared = scene.build.one_by_one;
    scratch_.sparse = scene.build.sparse.scratch;
  }

  Result<std::vector<BuiltStructure>> run() {
    RAYSPEC_TRY_VOID(describeBlases());
    RAYSPEC_TRY_VOID(createTopLevels());
    RAYSPEC_TRY(const VkDeviceAddress scratch, createScratch(ctx_, scratch_, guards_, cleanup_));
    placeScratch(scratch);
    if (scene_.build.command == BuildCommand::Indirect) RAYSPEC_TRY_VOID(placeRangesForIndirect());
    RAYSPEC_TRY(VkCommandBuffer cmd, beginCommands(ctx_, cleanup_));
    if (scene_.build.sparse.geometry) recordUploadBarrier(cmd);
    guards_.recordFill(cmd);
    RAYSPEC_TRY_VOID(runLevel(
        cmd, blases_, blas_updates_, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
        [this] { return queryBlases(); }, [this] { return copyBlases(); }));
    if (injectedLayoutFault() == LayoutFault::WritesPastSize) guards_.recordOverrun(cmd);
    RAYSPEC_TRY_VOID(writeAllInstances(cmd));
    RAYSPEC_TRY_VOID(runLevel(
        cmd, tlases_, tlas_updates_,
        VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR |
            VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
        [this] { return queryTlases(); }, [this] { return copyTlases(); }));
    RAYSPEC_TRY_VOID(submitAndWait(ctx_, cmd));
    RAYSPEC_TRY_VOID(checkGuards(since_copy_));
    return tlas_structures_;
  }

  // R-AS-MEMORY: each guard the builds, updates and copies changed.
  const std::vector<std::string>& overruns() const { return overruns_; }
  // R-AS-QUERY-*, R-AS-SERIAL-*: each answer of scene.build.queries that broke a guarantee.
  const std::vector<DeviceFinding>& queryFindings() const { return query_findings_; }

 private:
  const Scene& first() const { return *states_.front(); }
  size_t updates() const { return states_.size() - 1; }

  Result<void> placeRangesForIndirect() {
    for (Builds* b : {&blases_, &tlases_})
      RAYSPEC_TRY_VOID(b->placeRangesForIndirect(ctx_, cleanup_));
    for (auto* updates : {&blas_updates_, &tlas_updates_})
      for (Builds& b : *updates) RAYSPEC_TRY_VOID(b.placeRangesForIndirect(ctx_, cleanup_));
    return {};
  }

  void placeScratch(VkDeviceAddress base) {
    blases_.placeScratch(base);
    tlases_.placeScratch(base);
    for (Builds& b : blas_updates_) b.placeScratch(base);
    for (Builds& b : tlas_updates_) b.placeScratch(base);
  }

  // R-AS-MEMORY: the guards filled so far, each changed one not reported
  // before a line of overruns_ (`when`: which commands it follows).
  Result<void> checkGuards(const std::string& when) {
    RAYSPEC_TRY(const std::vector<std::string> changed, guards_.check(ctx_, cleanup_, when));
    overruns_.insert(overruns_.end(), changed.begin(), changed.end());
    return {};
  }

  // Once the copy of `levels` ended, the guards are checked, so that a guard
  // the commands after it change is not laid on the copy (or anything
  // before it); each check names the commands since the one before.
  Result<void> checkGuardsAtCopy(const std::string& levels) {
    RAYSPEC_TRY_VOID(checkGuards((since_copy_.empty() ? "" : since_copy_ + ", ") +
                                 "by the end of the copy of the " + levels));
    since_copy_ = "after the copy of the " + levels;
    return {};
  }

  // One level: its builds, then each update in turn, the queries and the
  // copy (submitted and waited on, then the updates after it retargeted to
  // the copies) where scene.build.order puts it.
  Result<void> runLevel(VkCommandBuffer& cmd, const Builds& builds,
                        const std::vector<Builds>& updates, VkPipelineStageFlags next,
                        const std::function<Result<void>()>& query,
                        const std::function<Result<void>()>& copy) {
    builds.record(ctx_, cmd, next, scene_.build.one_by_one);
    const size_t copy_at = copyAt(scene_), query_at = queryAt(scene_);
    for (size_t k = 0; k <= updates.size(); ++k) {
      if (k == copy_at || k == query_at) {
        RAYSPEC_TRY_VOID(submitAndWait(ctx_, cmd));
        if (k == query_at) RAYSPEC_TRY_VOID(query());
        if (k == copy_at) RAYSPEC_TRY_VOID(copy());
        RAYSPEC_TRY(cmd, beginCommands(ctx_, cleanup_));
        guards_.recordFill(cmd);  // those of structures the copy made room for
      }
      if (k == updates.size()) break;
      RAYSPEC_TRY_VOID(updates[k].checkRoom());
      updates[k].record(ctx_, cmd, next, scene_.build.one_by_one);
    }
    return {};
  }

  // The planted fault sparse-page-lost: each sparse input buffer loses its
  // second page once filled.
  static bool losesPage() { return injectedLayoutFault() == LayoutFault::SparsePageLost; }

  // A buffer of build inputs, filled by a copy: sparse, the contents
  // straddling a page boundary (scene.build.sparse geometry, instances).
  Result<SparseBuffer> sparseInputs(VkDeviceSize bytes) {
    return createSparseBuffer(ctx_, bytes, kInputUsage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              straddlingStart(bytes), cleanup_);
  }

  // The BLASes' input bytes in one buffer, host-visible or (scene.build.sparse
  // geometry) sparse: the address where they start.
  Result<VkDeviceAddress> uploadInputs(const std::vector<uint8_t>& bytes) {
    if (!scene_.build.sparse.geometry) {
      RAYSPEC_TRY(const Buffer inputs,
                  createUploadBuffer(ctx_, bytes.data(), bytes.size(), kInputUsage, cleanup_));
      return inputs.address;
    }
    RAYSPEC_TRY(const SparseBuffer inputs, sparseInputs(bytes.size()));
    RAYSPEC_TRY_VOID(
        uploadToSparse(ctx_, inputs, bytes.data(), bytes.size(), losesPage(), cleanup_));
    return inputs.buffer.address + inputs.offset;
  }

  // A state's instance buffer: host-visible, or (scene.build.sparse
  // instances) sparse, filled by a copy.
  Result<SparseBuffer> instanceBuffer() {
    if (scene_.build.sparse.instances) return sparseInputs(layout_->bytes());
    SparseBuffer whole;
    RAYSPEC_TRY(whole.buffer,
                createBuffer(ctx_, layout_->bytes(), kInputUsage, MemoryUse::Host, cleanup_));
    return whole;
  }

  // Every reached BLAS of the scene as first built, and the geometry each
  // update moves it to: one input buffer for all.
  Result<void> describeBlases() {
    const std::vector<bool> used = reachedBlases(first());
    InputPacker packer;
    builds_.resize(first().blases.size());
    updates_.assign(updates(), std::vector<BlasBuild>(first().blases.size()));
    for (size_t i = 0; i < first().blases.size(); ++i) {
      if (!used[i]) continue;
      describeBlas(first().blases[i], scene_.build, packer, builds_[i]);
      for (size_t k = 0; k < updates(); ++k)
        describeBlas(states_[k + 1]->blases[i], scene_.build, packer, updates_[k][i]);
    }
    if (!packer.bytes().empty()) {
      RAYSPEC_TRY(const VkDeviceAddress inputs, uploadInputs(packer.bytes()));
      for (BlasBuild& b : builds_) patchAddresses(b, inputs);
      for (auto& state : updates_)
        for (BlasBuild& b : state) patchAddresses(b, inputs);
    }
    RAYSPEC_TRY(blases_,
                createBlases(ctx_, builds_, used, flags_, making_, scratch_, guards_, cleanup_));
    for (const auto& state : updates_) {
      std::vector<const std::vector<VkAccelerationStructureGeometryKHR>*> geometries;
      std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> ranges;
      for (size_t i : blases_.blas) {
        geometries.push_back(&state[i].geometries);
        ranges.push_back(state[i].ranges.data());
      }
      blas_updates_.push_back(updatesOf(blases_, geometries, ranges, scratch_));
    }
    if (scene_.build.update_into_other && !blas_updates_.empty()) {
      RAYSPEC_TRY(const std::vector<VkAccelerationStructureKHR> last,
                  updateIntoOthers(ctx_, blas_updates_, blases_,
                                   VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, making_,
                                   guards_, cleanup_));
      for (size_t k = 0; k < last.size(); ++k) {  // the instances reference these
        BlasBuild& b = builds_[blases_.blas[k]];
        b.handle = last[k];
        b.address = structureAddress(ctx_, b.handle);
      }
    }
    return {};
  }

  // One TLAS per level, each over all instances (the other levels'
  // inactive); per update, their update to that state's instances.
  Result<void> createTopLevels() {
    const uint32_t levels = first().tlasCount();
    instance_count_ = static_cast<uint32_t>(first().instances.size());
    layout_.emplace(scene_.build, levels, instance_count_, injectedLayoutFault());
    for (uint32_t level = 0; level < levels; ++level) {
      VkAccelerationStructureBuildRangeInfoKHR range{};
      range.primitiveCount = instance_count_;
      range.primitiveOffset = layout_->primitiveOffset(level);
      tlas_ranges_.push_back(range);
    }
    for (size_t k = 0; k < states_.size(); ++k) {
      RAYSPEC_TRY(instances_.emplace_back(), instanceBuffer());
      const SparseBuffer& at = instances_.back();
      geometry_.push_back(instanceGeometry(at.buffer.address + at.offset, *layout_, levels));
    }
    RAYSPEC_TRY(tlases_, createTlases(ctx_, geometry_[0], instance_count_, tlas_ranges_, flags_,
                                      making_, scratch_, tlas_structures_, guards_, cleanup_));
    std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> ranges;
    for (const auto& range : tlas_ranges_) ranges.push_back(&range);
    for (size_t k = 1; k < states_.size(); ++k) {
      std::vector<const std::vector<VkAccelerationStructureGeometryKHR>*> geometries;
      for (const auto& g : geometry_[k]) geometries.push_back(&g);
      tlas_updates_.push_back(
          updatesOf(tlases_, geometries, ranges, scratch_, scene_.build.tlas_rebuilt));
    }
    if (scene_.build.update_into_other && !tlas_updates_.empty()) {
      RAYSPEC_TRY(const std::vector<VkAccelerationStructureKHR> last,
                  updateIntoOthers(ctx_, tlas_updates_, tlases_,
                                   VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, making_, guards_,
                                   cleanup_));
      for (size_t k = 0; k < last.size(); ++k) tlas_structures_[k].handle = last[k];
    }
    return {};
  }

  // The state's instances (and pointers to them) where the layout puts them:
  // written into the mapped buffer, or copied into the sparse one.
  Result<void> writeInstances(const Scene& scene, const SparseBuffer& to) const {
    const std::vector<uint8_t> bytes =
        layout_->write(allInstances(scene, builds_), to.buffer.address + to.offset);
    if (!to.buffer.mapped)
      return uploadToSparse(ctx_, to, bytes.data(), bytes.size(), losesPage(), cleanup_);
    std::memcpy(to.buffer.mapped, bytes.data(), bytes.size());
    return {};
  }

  // Every state's instances, once the BLASes are final. Sparse instance
  // buffers are filled by copies of their own: the commands recorded so far
  // are submitted first, and the top levels' builds wait for the copies.
  Result<void> writeAllInstances(VkCommandBuffer& cmd) {
    const bool sparse = scene_.build.sparse.instances;
    if (sparse) RAYSPEC_TRY_VOID(submitAndWait(ctx_, cmd));
    for (size_t k = 0; k < states_.size(); ++k)
      RAYSPEC_TRY_VOID(writeInstances(*states_[k], instances_[k]));
    if (!sparse) return {};
    RAYSPEC_TRY(cmd, beginCommands(ctx_, cleanup_));
    recordUploadBarrier(cmd);
    guards_.recordFill(cmd);
    return {};
  }

  // The updates from the copy on act on the copies (R-AS-COPY, R-AS-UPDATE):
  // an update reads and writes its structure in place, a rebuild
  // (tlas_update rebuild, MODE_BUILD) only writes it. room: each one's room
  // for a build (Builds::room).
  static void retarget(std::vector<Builds>& updates, size_t from,
                       const std::vector<BuiltStructure>& structures,
                       const std::vector<VkDeviceSize>& room) {
    for (size_t k = from; k < updates.size(); ++k)
      for (size_t i = 0; i < updates[k].infos.size() && i < structures.size(); ++i) {
        VkAccelerationStructureBuildGeometryInfoKHR& info = updates[k].infos[i];
        info.dstAccelerationStructure = structures[i].handle;
        info.srcAccelerationStructure = info.mode == VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR
                                            ? structures[i].handle
                                            : VK_NULL_HANDLE;
        updates[k].room[i] = room[i];
      }
  }

  // Each copy's room for a build: its size, but none for a compacted copy
  // (a compacted size is enough only to update it, however large).
  std::vector<VkDeviceSize> roomOf(const std::vector<BuiltStructure>& copies) const {
    std::vector<VkDeviceSize> room;
    for (const BuiltStructure& s : copies)
      room.push_back(scene_.build.copy == AsCopy::Compact ? 0 : s.size);
    return room;
  }

  // The BLASes as the instances reference them now.
  std::vector<BuiltStructure> currentBlases() const {
    std::vector<BuiltStructure> from;
    for (size_t k = 0; k < blases_.blas.size(); ++k) {
      const BlasBuild& b = builds_[blases_.blas[k]];
      from.push_back({b.handle, b.size, blases_.names[k]});
    }
    return from;
  }

  // scene.build.queries of the BLASes (vulkan/structure_queries.h).
  Result<void> queryBlases() {
    return checkStructureQueries(ctx_, scene_.build.queries, {currentBlases(), false, {}},
                                 injectedLayoutFault(), guards_, cleanup_, query_findings_);
  }

  // scene.build.queries of the TLASes, each with the addresses of the
  // BLASes its instances reference (in the state they were built or last
  // updated to).
  Result<void> queryTlases() {
    QueriedLevel level{tlas_structures_, true, {}};
    const Scene& state = *states_[std::min(queryAt(scene_), updates())];
    for (const std::set<uint32_t>& blases : referencedBlases(state)) {
      std::set<VkDeviceAddress>& addresses = level.referenced.emplace_back();
      for (uint32_t i : blases) addresses.insert(builds_[i].address);
    }
    return checkStructureQueries(ctx_, scene_.build.queries, level, injectedLayoutFault(), guards_,
                                 cleanup_, query_findings_);
  }

  // R-AS-COPY: the BLASes replaced by their copies (the instance buffers,
  // written after, reference the copies).
  Result<void> copyBlases() {
    const std::vector<BuiltStructure> from = currentBlases();
    RAYSPEC_TRY(const std::vector<BuiltStructure> to,
                copyStructures(ctx_, from, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, making_,
                               scene_.build.copy, guards_, cleanup_));
    RAYSPEC_TRY_VOID(checkGuardsAtCopy("bottom levels"));
    for (size_t k = 0; k < to.size(); ++k) {
      BlasBuild& b = builds_[blases_.blas[k]];
      b.handle = to[k].handle;
      b.size = to[k].size;
      b.address = structureAddress(ctx_, b.handle);
    }
    retarget(blas_updates_, scene_.updatesBeforeCopy(), to, roomOf(to));
    return {};
  }

  // The TLASes replaced by their copies (or, to be rebuilt, by structures
  // with room for a build).
  Result<void> copyTlases() {
    RAYSPEC_TRY(tlas_structures_,
                copyStructures(ctx_, tlas_structures_, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                               making_, scene_.build.copy, guards_, cleanup_));
    RAYSPEC_TRY_VOID(checkGuardsAtCopy("top levels"));
    std::vector<VkDeviceSize> room = roomOf(tlas_structures_);
    if (scene_.build.tlas_rebuilt && scene_.updatesBeforeCopy() < updates())
      RAYSPEC_TRY_VOID(makeRoomForRebuilds(room));
    retarget(tlas_updates_, scene_.updatesBeforeCopy(), tlas_structures_, room);
    return {};
  }

  // R-AS-UPDATE by rebuild after the copy (tlas_update rebuild): a build
  // (MODE_BUILD) needs a destination of the build's accelerationStructureSize
  // (VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-10126, formerly 03675:
  // a compacted size is enough only to update a compacted structure). A top
  // level whose copy has no room for it (a compacted copy, whatever its
  // size: roomOf) is rebuilt into a new structure of that size, which the
  // traces then use; a clone has the room, and is rebuilt itself.
  Result<void> makeRoomForRebuilds(std::vector<VkDeviceSize>& room) {
    for (size_t i = 0; i < tlas_structures_.size(); ++i) {
      const VkDeviceSize size = tlases_.sizes[i];
      if (room[i] >= size) continue;
      const std::string name = tlases_.names[i];
      RAYSPEC_TRY(const VkAccelerationStructureKHR into,
                  createStructure(ctx_, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, making_, size,
                                  cleanup_, guards_,
                                  "the structure " + name +
                                      " is rebuilt into after its copy, its "
                                      "accelerationStructureSize"));
      tlas_structures_[i] = {into, size, name};
      room[i] = size;
    }
    return {};
  }

  const VulkanContext& ctx_;
  const Scene& scene_;                // as the traces see it
  std::vector<const Scene*> states_;  // as first built, after each update (the last: scene_)
  const VkBuildAccelerationStructureFlagsKHR flags_;  // every build's and update's
  const StructureMaking making_;
  Cleanup& cleanup_;
  ScratchPlan scratch_;
  MemoryGuards guards_;
  std::vector<std::string> overruns_;
  std::vector<DeviceFinding> query_findings_;
  std::string since_copy_;  // "after the copy of the top levels": what the last guard check follows
  std::vector<BlasBuild> builds_;
  std::vector<std::vector<BlasBuild>> updates_;  // per update: each BLAS's new geometry
  Builds blases_, tlases_;
  std::vector<Builds> blas_updates_, tlas_updates_;  // per update
  uint32_t instance_count_ = 0;
  std::optional<InstanceLayout> layout_;
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> tlas_ranges_;                   // per level
  std::vector<SparseBuffer> instances_;                                                 // per state
  std::vector<std::vector<std::vector<VkAccelerationStructureGeometryKHR>>> geometry_;  // per state
  std::vector<BuiltStructure> tlas_structures_;
};

}  // namespace

namespace {

// One scene's builds (in the arena, if any); its overruns joined to
// `overruns`, its query findings to `query_findings`.
Result<std::vector<BuiltStructure>> buildOnce(const VulkanContext& ctx, const Scene& scene,
                                              VkBuildAccelerationStructureFlagsKHR extra_flags,
                                              StructureArena* arena, Cleanup& cleanup,
                                              std::vector<std::string>& overruns,
                                              std::vector<DeviceFinding>& query_findings,
                                              const std::string& what = "") {
  SceneBuilder builder(ctx, scene, extra_flags, arena, cleanup);
  RAYSPEC_TRY(std::vector<BuiltStructure> tlases, builder.run());
  for (const std::string& o : builder.overruns()) overruns.push_back(what + o);
  for (const DeviceFinding& f : builder.queryFindings()) query_findings.push_back(f);
  return tlases;
}

// scene.build.storage reused: the decoy scene built in the arena, waited on
// (SceneBuilder::run submits and waits) and destroyed, the arena rewound so
// that the scene's structures take the decoy's memory.
Result<void> buildDecoy(const VulkanContext& ctx, const Scene& scene,
                        VkBuildAccelerationStructureFlagsKHR extra_flags, StructureArena& arena,
                        std::vector<std::string>& overruns) {
  Cleanup decoy;
  Scene decoy_scene = decoyScene(scene);
  decoy_scene.build.queries = {};  // the decoy is not queried
  std::vector<DeviceFinding> unasked;
  RAYSPEC_TRY_VOID(buildOnce(ctx, decoy_scene, extra_flags, &arena, decoy, overruns, unasked,
                             "the decoy built first in the memory of the structures: "));
  decoy.run();
  arena.rewind();
  return {};
}

}  // namespace

Result<std::vector<BuiltStructure>> buildScene(const VulkanContext& ctx, const Scene& scene,
                                               VkBuildAccelerationStructureFlagsKHR extra_flags,
                                               Cleanup& cleanup, std::vector<std::string>& overruns,
                                               std::vector<DeviceFinding>& query_findings) {
  overruns.clear();
  query_findings.clear();
  const StructureStorage storage = scene.build.storage;
  if (storage == StructureStorage::Own)
    return buildOnce(ctx, scene, extra_flags, nullptr, cleanup, overruns, query_findings);
  StructureArena arena(cleanup);
  if (storage == StructureStorage::Reused)
    RAYSPEC_TRY_VOID(buildDecoy(ctx, scene, extra_flags, arena, overruns));
  RAYSPEC_TRY(std::vector<BuiltStructure> tlases,
              buildOnce(ctx, scene, extra_flags, &arena, cleanup, overruns, query_findings));
  if (storage == StructureStorage::Reused)
    RAYSPEC_TRY_VOID(createOverlays(ctx, arena, injectedLayoutFault(), cleanup));
  return tlases;
}

}  // namespace rayspec
