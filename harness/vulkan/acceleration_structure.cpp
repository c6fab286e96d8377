#include "vulkan/acceleration_structure.h"

#include <string>

#include "case/flag_names.h"
#include "vulkan/build_log.h"
#include "vulkan/memory.h"
#include "vulkan/sparse_buffer.h"
#include "vulkan/structure_arena.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

constexpr VkBufferUsageFlags kStorageUsage =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
    VK_BUFFER_USAGE_TRANSFER_DST_BIT;

// A structure's buffer and where in it the structure starts: bound whole, or
// sparsely with the structure across the first page boundary.
// Host-visible where the host queries it (scene.build.query_command host).
Result<SparseBuffer> storageFor(const VulkanContext& ctx, VkDeviceSize size,
                                const StructureMaking& making, Cleanup& cleanup) {
  if (making.sparse)
    return createSparseBuffer(ctx, guardedSize(size), kStorageUsage, kBeforePageBoundary, cleanup);
  SparseBuffer whole;
  RAYSPEC_TRY(whole.buffer,
              createBuffer(ctx, guardedSize(size), kStorageUsage,
                           making.host_visible ? MemoryUse::Host : MemoryUse::Device, cleanup));
  return whole;
}

}  // namespace

VkAccelerationStructureTypeKHR StructureMaking::createdAs(
    VkAccelerationStructureTypeKHR level) const {
  const bool bottom = level == VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
  const bool named = generic == GenericLevels::Both ||
                     generic == (bottom ? GenericLevels::Bottom : GenericLevels::Top);
  return named ? VK_ACCELERATION_STRUCTURE_TYPE_GENERIC_KHR : level;
}

Result<VkAccelerationStructureKHR> createStructure(const VulkanContext& ctx,
                                                   VkAccelerationStructureTypeKHR level,
                                                   const StructureMaking& making, VkDeviceSize size,
                                                   Cleanup& cleanup, MemoryGuards& guards,
                                                   const std::string& what) {
  const VkAccelerationStructureTypeKHR created = making.createdAs(level);
  RAYSPEC_TRY(const SparseBuffer storage, making.arena ? making.arena->place(ctx, size, created)
                                                       : storageFor(ctx, size, making, cleanup));
  guards.add(storage.buffer.buffer, storage.offset, size,
             what + " (" + std::to_string(size) + " bytes)");
  VkAccelerationStructureCreateInfoKHR info{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  info.buffer = storage.buffer.buffer;
  info.offset = storage.offset;
  info.size = size;
  info.type = created;
  return createStructureOver(ctx, info, level, storage.page, cleanup);
}

Result<VkAccelerationStructureKHR> createStructureOver(
    const VulkanContext& ctx, const VkAccelerationStructureCreateInfoKHR& info,
    VkAccelerationStructureTypeKHR level, VkDeviceSize page, Cleanup& cleanup) {
  VkAccelerationStructureKHR as = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(vkCheck(ctx.fn.createAccelerationStructure(ctx.device, &info, nullptr, &as),
                           "vkCreateAccelerationStructureKHR"));
  VkDevice device = ctx.device;
  auto destroy = ctx.fn.destroyAccelerationStructure;
  cleanup.add([device, destroy, as] { destroy(device, as, nullptr); });
  if (BuildLog* log = buildLog())
    log->structures.push_back({as, info.type, level, info.offset, info.size, page, info.buffer});
  return as;
}

VkFormat vkVertexFormat(VertexFormat f) {
#define RAYSPEC_VK_VERTEX_FORMAT(id, name, vk, ...) \
  case VertexFormat::id:                            \
    return VK_FORMAT_##vk;
  switch (f) { RAYSPEC_VERTEX_FORMATS(RAYSPEC_VK_VERTEX_FORMAT) }
#undef RAYSPEC_VK_VERTEX_FORMAT
  return VK_FORMAT_R32G32B32_SFLOAT;
}

VkBuildAccelerationStructureFlagsKHR buildFlags(const AsBuild& build) {
  const bool compacted =
      build.copy == AsCopy::Compact || build.queries.asks(StructureQuery::CompactedSize);
  return build.flags | (compacted ? kBuildAllowCompaction : 0u);
}

std::vector<bool> reachedBlases(const Scene& scene) {
  std::vector<bool> used(scene.blases.size(), false);
  for (const Instance& inst : scene.instances)
    if (inst.blas && *inst.blas < scene.blases.size()) used[*inst.blas] = true;
  return used;
}

VkDeviceAddress structureAddress(const VulkanContext& ctx, VkAccelerationStructureKHR as) {
  VkAccelerationStructureDeviceAddressInfoKHR ai{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  ai.accelerationStructure = as;
  return ctx.fn.getAccelerationStructureDeviceAddress(ctx.device, &ai);
}

}  // namespace rayspec
