#include "vulkan/level_builds.h"

#include <cstring>
#include <string>

#include "case/flag_names.h"

namespace rayspec {
namespace {

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

// What the guard after a build's scratch region calls it.
std::string scratchName(const std::string& structure,
                        const VkAccelerationStructureBuildSizesInfoKHR& sizes) {
  return "the build scratch of " + structure + " (buildScratchSize " +
         std::to_string(sizes.buildScratchSize) + " bytes)";
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
    vi.instanceCustomIndex = inst.custom_index & kInstanceFieldMask;
    vi.mask = inst.mask & kVisibilityMask;
    vi.instanceShaderBindingTableRecordOffset = inst.sbt_offset & kInstanceFieldMask;
    vi.flags = inst.flags & kInstanceFlagsMask;
    vi.accelerationStructureReference =
        inst.tlas == level && inst.blas && *inst.blas < builds.size() ? builds[*inst.blas].address
                                                                      : 0;
    instances.push_back(vi);
  }
  return instances;
}

}  // namespace

Result<Builds> createBlases(const VulkanContext& ctx, std::vector<BlasBuild>& builds,
                            const std::vector<bool>& used,
                            VkBuildAccelerationStructureFlagsKHR flags,
                            const StructureMaking& making, ScratchPlan& scratch,
                            MemoryGuards& guards, Cleanup& cleanup) {
  Builds out;
  for (size_t i = 0; i < builds.size(); ++i) {
    if (!used[i]) continue;
    BlasBuild& b = builds[i];
    VkAccelerationStructureBuildGeometryInfoKHR info =
        buildInfo(VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, b.geometries, flags);
    VkAccelerationStructureBuildSizesInfoKHR sizes{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    ctx.fn.getAccelerationStructureBuildSizes(ctx.device,
                                              VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                              &info, b.max_primitives.data(), &sizes);
    b.size = sizes.accelerationStructureSize;
    const std::string name = "BLAS " + std::to_string(i);
    RAYSPEC_TRY(b.handle,
                createStructure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, making,
                                b.size, cleanup, guards, name + ", its accelerationStructureSize"));
    info.dstAccelerationStructure = b.handle;
    b.address = structureAddress(ctx, b.handle);
    out.add(info, b.ranges.data(), scratch.add(sizes.buildScratchSize, scratchName(name, sizes)));
    out.names.push_back(name);
    out.update_scratch.push_back(sizes.updateScratchSize);
    out.build_scratch.push_back(sizes.buildScratchSize);
    out.sizes.push_back(b.size);
    out.room.push_back(b.size);
    out.blas.push_back(i);
  }
  return out;
}

std::vector<VkAccelerationStructureInstanceKHR> allInstances(const Scene& scene,
                                                             const std::vector<BlasBuild>& builds) {
  std::vector<VkAccelerationStructureInstanceKHR> instances;
  for (uint32_t level = 0; level < scene.tlasCount(); ++level) {
    const auto own = tlasInstances(scene, builds, level);
    instances.insert(instances.end(), own.begin(), own.end());
  }
  return instances;
}

std::vector<std::vector<VkAccelerationStructureGeometryKHR>> instanceGeometry(
    VkDeviceAddress instances, const InstanceLayout& layout, uint32_t levels) {
  std::vector<std::vector<VkAccelerationStructureGeometryKHR>> out(levels);
  for (uint32_t level = 0; level < levels; ++level) {
    VkAccelerationStructureGeometryKHR g{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    g.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    g.geometry.instances.sType =
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
    g.geometry.instances.arrayOfPointers = layout.pointers() ? VK_TRUE : VK_FALSE;
    g.geometry.instances.data.deviceAddress = instances + layout.dataOffset(level);
    out[level].push_back(g);
  }
  return out;
}

Result<Builds> createTlases(
    const VulkanContext& ctx,
    const std::vector<std::vector<VkAccelerationStructureGeometryKHR>>& geometry,
    uint32_t instance_count, const std::vector<VkAccelerationStructureBuildRangeInfoKHR>& ranges,
    VkBuildAccelerationStructureFlagsKHR flags, const StructureMaking& making, ScratchPlan& scratch,
    std::vector<BuiltStructure>& structures, MemoryGuards& guards, Cleanup& cleanup) {
  Builds out;
  for (size_t level = 0; level < geometry.size(); ++level) {
    const auto& g = geometry[level];
    VkAccelerationStructureBuildGeometryInfoKHR info =
        buildInfo(VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, g, flags);
    VkAccelerationStructureBuildSizesInfoKHR sizes{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    ctx.fn.getAccelerationStructureBuildSizes(ctx.device,
                                              VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                              &info, &instance_count, &sizes);
    const std::string name = "TLAS " + std::to_string(level);
    RAYSPEC_TRY(info.dstAccelerationStructure,
                createStructure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, making,
                                sizes.accelerationStructureSize, cleanup, guards,
                                name + ", its accelerationStructureSize"));
    structures.push_back({info.dstAccelerationStructure, sizes.accelerationStructureSize, name});
    out.add(info, &ranges[level], scratch.add(sizes.buildScratchSize, scratchName(name, sizes)));
    out.names.push_back(name);
    out.update_scratch.push_back(sizes.updateScratchSize);
    out.build_scratch.push_back(sizes.buildScratchSize);
    out.sizes.push_back(sizes.accelerationStructureSize);
    out.room.push_back(sizes.accelerationStructureSize);
  }
  return out;
}

Result<std::vector<VkAccelerationStructureKHR>> updateIntoOthers(
    const VulkanContext& ctx, std::vector<Builds>& updates, const Builds& built,
    VkAccelerationStructureTypeKHR type, const StructureMaking& making, MemoryGuards& guards,
    Cleanup& cleanup) {
  std::vector<VkAccelerationStructureKHR> current;
  for (const auto& info : built.infos) current.push_back(info.dstAccelerationStructure);
  for (size_t k = 0; k < updates.size(); ++k)
    for (size_t i = 0; i < updates[k].infos.size(); ++i) {
      Builds& update = updates[k];
      RAYSPEC_TRY(
          VkAccelerationStructureKHR into,
          createStructure(ctx, type, making, built.sizes[i], cleanup, guards,
                          "the structure update " + std::to_string(k + 1) + " of " +
                              built.names[i] + " wrote into, its accelerationStructureSize"));
      if (update.infos[i].mode == VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR)
        update.infos[i].srcAccelerationStructure = current[i];
      update.infos[i].dstAccelerationStructure = into;
      current[i] = into;
    }
  return current;
}

}  // namespace rayspec
