#include "vulkan/acceleration_copy.h"

#include <cstring>

#include "base/align.h"

#include "vulkan/acceleration_structure.h"
#include "vulkan/build_batch.h"
#include "vulkan/commands.h"
#include "vulkan/memory.h"
#include "vulkan/structure_queries.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

// A size of each structure the device reports (compacted or serialized),
// through a query pool (vulkan/structure_queries.h).
Result<std::vector<VkDeviceSize>> queriedSizes(const VulkanContext& ctx,
                                               const std::vector<BuiltStructure>& from,
                                               VkQueryType query, Cleanup& cleanup) {
  RAYSPEC_TRY(const QueriedValues read, queryProperty(ctx, handlesOf(from), query, cleanup));
  return read.values;
}

// The compacted size of each structure, as the device reports it.
Result<std::vector<VkDeviceSize>> compactedSizes(const VulkanContext& ctx,
                                                 const std::vector<BuiltStructure>& from,
                                                 Cleanup& cleanup) {
  RAYSPEC_TRY(
      const std::vector<VkDeviceSize> sizes,
      queriedSizes(ctx, from, VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, cleanup));
  for (size_t i = 0; i < sizes.size(); ++i)
    if (sizes[i] == 0 || sizes[i] > from[i].size)
      return deviceError("compacted size " + std::to_string(sizes[i]) + " of " + from[i].name +
                         ", a structure of " + std::to_string(from[i].size) +
                         " bytes: VK_ERROR_UNKNOWN");
  return sizes;
}

// The header of each serialized copy checked before it is deserialized:
// the device must call its own data compatible, and the sizes must be
// those it reported (a Device error otherwise; scene.build.queries holds
// the header to every rule instead, vulkan/structure_queries.h).
Result<void> checkHeaders(const VulkanContext& ctx, const SerializedCopies& s) {
  for (size_t i = 0; i < s.sizes.size(); ++i) {
    const SerializedHeader h = s.header(i);
    if (!deviceCallsCompatible(ctx, s.data(i)))
      return deviceError(
          "vkGetDeviceAccelerationStructureCompatibilityKHR calls the device's own serialized "
          "structure incompatible: VK_ERROR_INCOMPATIBLE_DRIVER");
    if (h.serialized_size != s.sizes[i])
      return deviceError("serialized data says it holds " + std::to_string(h.serialized_size) +
                         " bytes, the query said " + std::to_string(s.sizes[i]) +
                         ": VK_ERROR_UNKNOWN");
  }
  return {};
}

// R-AS-COPY by serialization: each structure to memory, then from memory
// into a new structure of the size the data names.
Result<std::vector<BuiltStructure>> serializeAndBack(const VulkanContext& ctx,
                                                     const std::vector<BuiltStructure>& from,
                                                     VkAccelerationStructureTypeKHR type,
                                                     const StructureMaking& making,
                                                     MemoryGuards& guards, Cleanup& cleanup) {
  RAYSPEC_TRY(SerializedCopies s, serializeToHost(ctx, from, guards, cleanup));
  RAYSPEC_TRY_VOID(checkHeaders(ctx, s));
  std::vector<BuiltStructure> to;
  RAYSPEC_TRY(VkCommandBuffer cmd, beginCommands(ctx, cleanup));
  for (size_t i = 0; i < from.size(); ++i) {
    const VkDeviceSize size = s.deserializedSize(i);
    RAYSPEC_TRY(
        const VkAccelerationStructureKHR copy_handle,
        createStructure(ctx, type, making, size, cleanup, guards,
                        from[i].name + " deserialized, the deserialized size its data names"));
    to.push_back({copy_handle, size, from[i].name});
  }
  guards.recordFill(cmd);
  for (size_t i = 0; i < from.size(); ++i) {
    VkCopyMemoryToAccelerationStructureInfoKHR copy{
        VK_STRUCTURE_TYPE_COPY_MEMORY_TO_ACCELERATION_STRUCTURE_INFO_KHR};
    copy.src.deviceAddress = s.memory.address + s.offsets[i];
    copy.dst = to[i].handle;
    copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_DESERIALIZE_KHR;
    ctx.fn.cmdCopyMemoryToAccelerationStructure(cmd, &copy);
  }
  recordStructureBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR |
                                  VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);
  RAYSPEC_TRY_VOID(submitAndWait(ctx, cmd));
  return to;
}

}  // namespace

std::vector<VkAccelerationStructureKHR> handlesOf(const std::vector<BuiltStructure>& from) {
  std::vector<VkAccelerationStructureKHR> handles;
  for (const BuiltStructure& s : from) handles.push_back(s.handle);
  return handles;
}

SerializedHeader SerializedCopies::header(size_t i) const {
  const uint8_t* d = data(i);
  SerializedHeader h;
  std::memcpy(h.driver_uuid.data(), d, VK_UUID_SIZE);
  std::memcpy(h.compatibility_uuid.data(), d + VK_UUID_SIZE, VK_UUID_SIZE);
  std::memcpy(&h.serialized_size, d + 2 * VK_UUID_SIZE, 8);
  std::memcpy(&h.deserialized_size, d + kDeserializedSizeOffset, 8);
  return h;
}

const uint8_t* SerializedCopies::data(size_t i) const {
  return static_cast<const uint8_t*>(memory.mapped) + offsets[i];
}

VkDeviceSize SerializedCopies::deserializedSize(size_t i) const {
  return header(i).deserialized_size;
}

bool deviceCallsCompatible(const VulkanContext& ctx, const uint8_t* version_data) {
  VkAccelerationStructureVersionInfoKHR version{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_VERSION_INFO_KHR};
  version.pVersionData = version_data;
  VkAccelerationStructureCompatibilityKHR compatible =
      VK_ACCELERATION_STRUCTURE_COMPATIBILITY_INCOMPATIBLE_KHR;
  ctx.fn.getDeviceAccelerationStructureCompatibility(ctx.device, &version, &compatible);
  return compatible == VK_ACCELERATION_STRUCTURE_COMPATIBILITY_COMPATIBLE_KHR;
}

Result<SerializedCopies> serializeToHost(const VulkanContext& ctx,
                                         const std::vector<BuiltStructure>& from,
                                         MemoryGuards& guards, Cleanup& cleanup) {
  RAYSPEC_TRY(const std::vector<VkDeviceSize> sizes,
              queriedSizes(ctx, from, VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SERIALIZATION_SIZE_KHR,
                           cleanup));
  for (size_t i = 0; i < sizes.size(); ++i)
    if (sizes[i] < kSerializedHeaderBytes)
      return deviceError("the serialization size query gave " + std::to_string(sizes[i]) +
                         " bytes for " + from[i].name +
                         ", less than the header every serialized structure holds: "
                         "VK_ERROR_UNKNOWN");
  SerializedCopies s;
  s.sizes = sizes;
  VkDeviceSize total = 0;
  for (VkDeviceSize size : sizes) {
    s.offsets.push_back(total);
    total += alignUp(guardedSize(size), kSerializedAlignment);
  }
  RAYSPEC_TRY(
      s.memory,
      createBuffer(ctx, total + kSerializedAlignment,
                   VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                       VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                       VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                   MemoryUse::Host, cleanup));
  const VkDeviceSize base = alignUp(s.memory.address, kSerializedAlignment) - s.memory.address;
  for (VkDeviceSize& offset : s.offsets) offset += base;
  RAYSPEC_TRY(VkCommandBuffer cmd, beginCommands(ctx, cleanup));
  for (size_t i = 0; i < from.size(); ++i)
    guards.add(s.memory.buffer, s.offsets[i], sizes[i],
               from[i].name + " serialized (" + std::to_string(sizes[i]) +
                   " bytes, its serialization size)");
  guards.recordFill(cmd);
  for (size_t i = 0; i < from.size(); ++i) {
    VkCopyAccelerationStructureToMemoryInfoKHR copy{
        VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_TO_MEMORY_INFO_KHR};
    copy.src = from[i].handle;
    copy.dst.deviceAddress = s.memory.address + s.offsets[i];
    copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_SERIALIZE_KHR;
    ctx.fn.cmdCopyAccelerationStructureToMemory(cmd, &copy);
  }
  // The serialized bytes, written as transfers in the build stage, read by
  // the host.
  recordMemoryBarrier(cmd, {kBuildStage, VK_ACCESS_TRANSFER_WRITE_BIT},
                      {VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT});
  RAYSPEC_TRY_VOID(submitAndWait(ctx, cmd));
  return s;
}

Result<std::vector<BuiltStructure>> copyStructures(const VulkanContext& ctx,
                                                   const std::vector<BuiltStructure>& from,
                                                   VkAccelerationStructureTypeKHR type,
                                                   const StructureMaking& making, AsCopy mode,
                                                   MemoryGuards& guards, Cleanup& cleanup) {
  if (from.empty() || mode == AsCopy::None) return from;
  if (mode == AsCopy::Serialize) return serializeAndBack(ctx, from, type, making, guards, cleanup);
  std::vector<VkDeviceSize> sizes;
  for (const BuiltStructure& s : from) sizes.push_back(s.size);
  if (mode == AsCopy::Compact) {
    RAYSPEC_TRY(sizes, compactedSizes(ctx, from, cleanup));
  }
  std::vector<BuiltStructure> to;
  RAYSPEC_TRY(VkCommandBuffer cmd, beginCommands(ctx, cleanup));
  for (size_t i = 0; i < from.size(); ++i) {
    RAYSPEC_TRY(
        const VkAccelerationStructureKHR copy_handle,
        createStructure(
            ctx, type, making, sizes[i], cleanup, guards,
            "the " + std::string(mode == AsCopy::Compact ? "compacted" : "cloned") + " copy of " +
                from[i].name +
                (mode == AsCopy::Compact ? ", its compacted size" : ", the source's size")));
    to.push_back({copy_handle, sizes[i], from[i].name});
  }
  guards.recordFill(cmd);
  for (size_t i = 0; i < from.size(); ++i) {
    VkCopyAccelerationStructureInfoKHR copy{VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR};
    copy.src = from[i].handle;
    copy.dst = to[i].handle;
    copy.mode = mode == AsCopy::Compact ? VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR
                                        : VK_COPY_ACCELERATION_STRUCTURE_MODE_CLONE_KHR;
    ctx.fn.cmdCopyAccelerationStructure(cmd, &copy);
  }
  recordStructureBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR |
                                  VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);
  RAYSPEC_TRY_VOID(submitAndWait(ctx, cmd));
  return to;
}

}  // namespace rayspec
