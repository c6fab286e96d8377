// Copies of acceleration structures (scene.build.copy, R-AS-COPY): clones at
// the size they were created with, or compacted copies at the size the
// device reports after the build (a query pool of
// VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR), or serialized
// to host-visible memory and deserialized into new structures (the data's
// header checked: compatible with the device, the sizes it reported). Each
// step is a submission of its own, waited on.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "case/case.h"
#include "vulkan/acceleration_structure.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/memory.h"
#include "vulkan/memory_guards.h"

namespace rayspec {

// Serialized data (the specification's serialized-as-header): driverUUID,
// the compatibility UUID, then 64-bit sizes (the serialized size, the
// deserialized size; a top level: the handle count, then the handles).
constexpr VkDeviceSize kSerializedAlignment = 256;  // of src / dst device addresses
constexpr VkDeviceSize kDeserializedSizeOffset = 2 * VK_UUID_SIZE + 8;
constexpr VkDeviceSize kHandleCountOffset = 2 * VK_UUID_SIZE + 16;
constexpr VkDeviceSize kSerializedHeaderBytes = 2 * VK_UUID_SIZE + 16;  // the two UUIDs, two sizes

struct SerializedHeader {
  std::array<uint8_t, VK_UUID_SIZE> driver_uuid{}, compatibility_uuid{};
  uint64_t serialized_size = 0, deserialized_size = 0;
};

// Each structure serialized into host-visible memory (one buffer, each at a
// 256-byte aligned offset), at the serialization size the device reported
// (`sizes`), the bytes guarded after it (R-AS-MEMORY).
struct SerializedCopies {
  Buffer memory;
  std::vector<VkDeviceSize> offsets, sizes;
  const uint8_t* data(size_t i) const;
  SerializedHeader header(size_t i) const;
  VkDeviceSize deserializedSize(size_t i) const;
};

// The structures serialized (vkCmdCopyAccelerationStructureToMemoryKHR) at
// the size a query pool reports, readable by the host once this returns; or
// the Device error (a size smaller than the header).
Result<SerializedCopies> serializeToHost(const VulkanContext& ctx,
                                         const std::vector<BuiltStructure>& from,
                                         MemoryGuards& guards, Cleanup& cleanup);

// Whether vkGetDeviceAccelerationStructureCompatibilityKHR calls the
// serialized data at version_data (its two UUIDs) compatible.
bool deviceCallsCompatible(const VulkanContext& ctx, const uint8_t* version_data);

std::vector<VkAccelerationStructureKHR> handlesOf(const std::vector<BuiltStructure>& from);

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
