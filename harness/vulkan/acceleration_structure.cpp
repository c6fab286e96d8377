#include "vulkan/acceleration_structure.h"

#include <cstring>
#include <vector>

#include "case/flag_names.h"
#include "vulkan/acceleration_copy.h"
#include "vulkan/commands.h"
#include "vulkan/memory.h"
#include "vulkan/vk_check.h"

namespace rayspec {
VkAccelerationStructureKHR createStructure(const VulkanContext& ctx,
                                           VkAccelerationStructureTypeKHR type, VkDeviceSize size,
                                           Cleanup& cleanup) {
  Buffer storage = createBuffer(ctx, size,
                                VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                                    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                MemoryUse::Device, cleanup);
  VkAccelerationStructureCreateInfoKHR info{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  info.buffer = storage.buffer;
  info.size = size;
  info.type = type;
  VkAccelerationStructureKHR as = VK_NULL_HANDLE;
  vkCheck(ctx.fn.createAccelerationStructure(ctx.device, &info, nullptr, &as),
          "vkCreateAccelerationStructureKHR");
  VkDevice device = ctx.device;
  auto destroy = ctx.fn.destroyAccelerationStructure;
  cleanup.add([device, destroy, as] { destroy(device, as, nullptr); });
  return as;
}

void recordStructureBarrier(VkCommandBuffer cmd, VkPipelineStageFlags dst_stage) {
  VkMemoryBarrier mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  mb.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
  mb.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, dst_stage, 0, 1,
                       &mb, 0, nullptr, 0, nullptr);
}

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

struct BlasBuild {
  std::vector<VkAccelerationStructureGeometryKHR> geometries;
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges;
  std::vector<uint32_t> max_primitives;
  std::vector<uint64_t> offsets;  // per geometry: data, index, transform (packer offsets)
  VkAccelerationStructureKHR handle = VK_NULL_HANDLE;
  VkDeviceAddress address = 0;
  VkDeviceSize size = 0;  // accelerationStructureSize
};

constexpr uint64_t kNone = ~0ull;

// First pass: pack the inputs and fill the geometry descriptions with packer
// offsets; addresses are patched once the input buffer exists.
void describeBlas(const Blas& blas, InputPacker& packer, BlasBuild& b) {
  for (const Geometry& g : blas.geometries) {
    VkAccelerationStructureGeometryKHR geo{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    geo.flags = g.flags;
    uint32_t primitives = g.primitiveCount();
    uint64_t data = kNone, index = kNone, transform = kNone;
    if (g.kind == Geometry::Kind::Triangles) {
      geo.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
      auto& t = geo.geometry.triangles;
      t.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
      t.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
      t.vertexStride = sizeof(Vec3);
      t.maxVertex = g.vertices.empty() ? 0 : static_cast<uint32_t>(g.vertices.size() - 1);
      data = packer.add(g.vertices.data(), g.vertices.size() * sizeof(Vec3));
      t.indexType = g.indices.empty() ? VK_INDEX_TYPE_NONE_KHR : VK_INDEX_TYPE_UINT32;
      if (!g.indices.empty()) index = packer.add(g.indices.data(), g.indices.size() * 4);
      if (g.transform) {
        static_assert(sizeof(VkTransformMatrixKHR) == sizeof(Transform));
        transform = packer.add(g.transform->data(), sizeof(Transform));
      }
    } else {
      geo.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
      auto& a = geo.geometry.aabbs;
      a.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
      a.stride = sizeof(VkAabbPositionsKHR);
      static_assert(sizeof(VkAabbPositionsKHR) == sizeof(std::array<float, 6>));
      data = packer.add(g.aabbs.data(), g.aabbs.size() * sizeof(VkAabbPositionsKHR));
    }
    b.geometries.push_back(geo);
    b.offsets.insert(b.offsets.end(), {data, index, transform});
    VkAccelerationStructureBuildRangeInfoKHR range{};
    range.primitiveCount = primitives;
    b.ranges.push_back(range);
    b.max_primitives.push_back(primitives);
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

// scene.build's flags, and ALLOW_COMPACTION where the structures are compacted.
VkBuildAccelerationStructureFlagsKHR buildFlags(const AsBuild& build) {
  return build.flags | (build.copy == AsCopy::Compact ? kBuildAllowCompaction : 0u);
}

VkAccelerationStructureBuildGeometryInfoKHR buildInfo(
    VkAccelerationStructureTypeKHR type,
    const std::vector<VkAccelerationStructureGeometryKHR>& geos,
    VkBuildAccelerationStructureFlagsKHR flags) {
  VkAccelerationStructureBuildGeometryInfoKHR info{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  info.type = type;
  info.flags = flags;
  info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  info.geometryCount = static_cast<uint32_t>(geos.size());
  info.pGeometries = geos.data();
  return info;
}

// The builds of one command buffer and their places in one scratch buffer.
struct ScratchPlan {
  VkDeviceSize align = 0;
  VkDeviceSize total = 0;
  std::vector<VkDeviceSize> offsets;  // one a build, in order
  void add(VkDeviceSize size) {
    total = alignUp(total, align);
    offsets.push_back(total);
    total += size;
  }
};

// The BLAS builds: their structures created at the sizes the driver asks
// for, their scratch placed. Only BLASes some instance reaches are built.
struct BlasBuilds {
  std::vector<VkAccelerationStructureBuildGeometryInfoKHR> infos;
  std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> ranges;
};

VkDeviceAddress structureAddress(const VulkanContext& ctx, VkAccelerationStructureKHR as) {
  VkAccelerationStructureDeviceAddressInfoKHR ai{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  ai.accelerationStructure = as;
  return ctx.fn.getAccelerationStructureDeviceAddress(ctx.device, &ai);
}

std::vector<bool> reachedBlases(const Scene& scene) {
  std::vector<bool> used(scene.blases.size(), false);
  for (const Instance& inst : scene.instances)
    if (inst.blas && *inst.blas < scene.blases.size()) used[*inst.blas] = true;
  return used;
}

BlasBuilds createBlases(const VulkanContext& ctx, std::vector<BlasBuild>& builds,
                        const std::vector<bool>& used, VkDeviceAddress inputs,
                        VkBuildAccelerationStructureFlagsKHR flags, ScratchPlan& scratch,
                        Cleanup& cleanup) {
  BlasBuilds out;
  for (size_t i = 0; i < builds.size(); ++i) {
    if (!used[i]) continue;
    BlasBuild& b = builds[i];
    patchAddresses(b, inputs);
    VkAccelerationStructureBuildGeometryInfoKHR info =
        buildInfo(VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, b.geometries, flags);
    VkAccelerationStructureBuildSizesInfoKHR sizes{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    ctx.fn.getAccelerationStructureBuildSizes(ctx.device,
                                              VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                              &info, b.max_primitives.data(), &sizes);
    b.size = sizes.accelerationStructureSize;
    b.handle =
        createStructure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, b.size, cleanup);
    info.dstAccelerationStructure = b.handle;
    b.address = structureAddress(ctx, b.handle);
    scratch.add(sizes.buildScratchSize);
    out.infos.push_back(info);
    out.ranges.push_back(b.ranges.data());
  }
  return out;
}

// The instances of top level `level` as the device reads them: every
// instance of the scene, in order; a null BLAS, or an instance of another
// level, has address 0 (inactive, R-INACTIVE).
std::vector<VkAccelerationStructureInstanceKHR> tlasInstances(const Scene& scene,
                                                              const std::vector<BlasBuild>& builds,
                                                              uint32_t level) {
  std::vector<VkAccelerationStructureInstanceKHR> instances;
  for (const Instance& inst : scene.instances) {
    VkAccelerationStructureInstanceKHR vi{};
    std::memcpy(&vi.transform, inst.transform.data(), sizeof(vi.transform));
    vi.instanceCustomIndex = inst.custom_index & 0xFFFFFF;
    vi.mask = inst.mask & 0xFF;
    vi.instanceShaderBindingTableRecordOffset = inst.sbt_offset & 0xFFFFFF;
    vi.flags = inst.flags & 0xFF;
    vi.accelerationStructureReference =
        inst.tlas == level && inst.blas && *inst.blas < builds.size() ? builds[*inst.blas].address
                                                                      : 0;
    instances.push_back(vi);
  }
  return instances;
}

// The TLAS build over an instance buffer: its structure created, its scratch
// placed. `geometry` must outlive the build info that points to it.
VkAccelerationStructureBuildGeometryInfoKHR createTlas(
    const VulkanContext& ctx, VkDeviceAddress instances, uint32_t instance_count,
    VkBuildAccelerationStructureFlagsKHR flags,
    std::vector<VkAccelerationStructureGeometryKHR>& geometry, ScratchPlan& scratch,
    VkDeviceSize& size, Cleanup& cleanup) {
  geometry.assign(1, VkAccelerationStructureGeometryKHR{});
  geometry[0].sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR;
  geometry[0].geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  geometry[0].geometry.instances.sType =
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  geometry[0].geometry.instances.arrayOfPointers = VK_FALSE;
  geometry[0].geometry.instances.data.deviceAddress = instances;
  VkAccelerationStructureBuildGeometryInfoKHR info =
      buildInfo(VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, geometry, flags);
  VkAccelerationStructureBuildSizesInfoKHR sizes{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  ctx.fn.getAccelerationStructureBuildSizes(
      ctx.device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info, &instance_count, &sizes);
  size = sizes.accelerationStructureSize;
  info.dstAccelerationStructure =
      createStructure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, size, cleanup);
  scratch.add(sizes.buildScratchSize);
  return info;
}

// One scratch buffer for every build; its address aligned up to the
// scratch alignment. Returns that aligned address.
VkDeviceAddress createScratch(const VulkanContext& ctx, const ScratchPlan& scratch,
                              Cleanup& cleanup) {
  Buffer buffer =
      createBuffer(ctx, scratch.total + scratch.align,
                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                   MemoryUse::Device, cleanup);
  return alignUp(buffer.address, scratch.align);
}

// The instances of every top level, one level after the other, as the
// device reads them (tlasInstances).
std::vector<VkAccelerationStructureInstanceKHR> allInstances(const Scene& scene,
                                                             const std::vector<BlasBuild>& builds) {
  std::vector<VkAccelerationStructureInstanceKHR> instances;
  for (uint32_t level = 0; level < scene.tlasCount(); ++level) {
    const auto own = tlasInstances(scene, builds, level);
    instances.insert(instances.end(), own.begin(), own.end());
  }
  return instances;
}

// R-AS-COPY: the BLASes replaced by their copies, and the instance buffer
// rewritten to reference the copies.
void copyBlases(const VulkanContext& ctx, const Scene& scene, std::vector<BlasBuild>& builds,
                Buffer& instance_buffer, Cleanup& cleanup) {
  std::vector<BuiltStructure> from;
  for (const BlasBuild& b : builds)
    if (b.handle) from.push_back({b.handle, b.size});
  const std::vector<BuiltStructure> to = copyStructures(
      ctx, from, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, scene.build.copy, cleanup);
  size_t k = 0;
  for (BlasBuild& b : builds)
    if (b.handle) {
      b.handle = to[k].handle;
      b.size = to[k++].size;
      b.address = structureAddress(ctx, b.handle);
    }
  const auto instances = allInstances(scene, builds);
  std::memcpy(instance_buffer.mapped, instances.data(),
              instances.size() * sizeof(VkAccelerationStructureInstanceKHR));
}

}  // namespace

std::vector<VkAccelerationStructureKHR> buildScene(const VulkanContext& ctx, const Scene& scene,
                                                   Cleanup& cleanup) {
  const VkBuildAccelerationStructureFlagsKHR flags = buildFlags(scene.build);
  ScratchPlan scratch;
  scratch.align = ctx.as_props.minAccelerationStructureScratchOffsetAlignment;
  const std::vector<bool> used = reachedBlases(scene);
  InputPacker packer;
  std::vector<BlasBuild> builds(scene.blases.size());
  for (size_t i = 0; i < scene.blases.size(); ++i)
    if (used[i]) describeBlas(scene.blases[i], packer, builds[i]);
  Buffer inputs;
  if (!packer.bytes().empty())
    inputs =
        createUploadBuffer(ctx, packer.bytes().data(), packer.bytes().size(), kInputUsage, cleanup);
  BlasBuilds blases = createBlases(ctx, builds, used, inputs.address, flags, scratch, cleanup);

  // One TLAS per level, each over all instances (the other levels' inactive).
  const uint32_t levels = scene.tlasCount();
  const uint32_t instance_count = static_cast<uint32_t>(scene.instances.size());
  const auto instances = allInstances(scene, builds);
  Buffer instance_buffer = createUploadBuffer(
      ctx, instances.data(), instances.size() * sizeof(VkAccelerationStructureInstanceKHR),
      kInputUsage, cleanup);
  std::vector<std::vector<VkAccelerationStructureGeometryKHR>> tlas_geometry(levels);
  std::vector<VkAccelerationStructureBuildGeometryInfoKHR> tlas_infos;
  std::vector<BuiltStructure> tlases(levels);
  for (uint32_t level = 0; level < levels; ++level)
    tlas_infos.push_back(createTlas(
        ctx,
        instance_buffer.address +
            level * instance_count * sizeof(VkAccelerationStructureInstanceKHR),
        instance_count, flags, tlas_geometry[level], scratch, tlases[level].size, cleanup));

  const VkDeviceAddress scratch_base = createScratch(ctx, scratch, cleanup);
  for (size_t i = 0; i < blases.infos.size(); ++i)
    blases.infos[i].scratchData.deviceAddress = scratch_base + scratch.offsets[i];
  for (uint32_t level = 0; level < levels; ++level)
    tlas_infos[level].scratchData.deviceAddress =
        scratch_base + scratch.offsets[blases.infos.size() + level];

  VkCommandBuffer cmd = beginCommands(ctx, cleanup);
  if (!blases.infos.empty()) {
    ctx.fn.cmdBuildAccelerationStructures(cmd, static_cast<uint32_t>(blases.infos.size()),
                                          blases.infos.data(), blases.ranges.data());
    recordStructureBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR);
  }
  if (scene.build.copy != AsCopy::None) {
    submitAndWait(ctx, cmd, kBuildTimeoutNs);
    copyBlases(ctx, scene, builds, instance_buffer, cleanup);
    cmd = beginCommands(ctx, cleanup);
  }
  VkAccelerationStructureBuildRangeInfoKHR tlas_range{};
  tlas_range.primitiveCount = instance_count;
  const std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> tlas_ranges(levels,
                                                                                 &tlas_range);
  ctx.fn.cmdBuildAccelerationStructures(cmd, levels, tlas_infos.data(), tlas_ranges.data());
  recordStructureBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);
  submitAndWait(ctx, cmd, kBuildTimeoutNs);
  for (uint32_t level = 0; level < levels; ++level)
    tlases[level].handle = tlas_infos[level].dstAccelerationStructure;
  std::vector<VkAccelerationStructureKHR> out;
  for (const BuiltStructure& t : copyStructures(
           ctx, tlases, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, scene.build.copy, cleanup))
    out.push_back(t.handle);
  return out;
}

}  // namespace rayspec
