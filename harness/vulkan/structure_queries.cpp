#include "vulkan/structure_queries.h"

#include <cstring>

#include "base/hex_text.h"
#include "vulkan/acceleration_copy.h"
#include "vulkan/commands.h"
#include "vulkan/vk_check.h"

namespace rayspec {

VkQueryType vkQueryType(StructureQuery q) {
  switch (q) {
    case StructureQuery::CompactedSize:
      return VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR;
    case StructureQuery::SerializationSize:
      return VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SERIALIZATION_SIZE_KHR;
    case StructureQuery::Size:
      return VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SIZE_KHR;
    case StructureQuery::BottomLevelPointers:
      return VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SERIALIZATION_BOTTOM_LEVEL_POINTERS_KHR;
  }
  return VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SIZE_KHR;
}

namespace {

Result<VkQueryPool> createQueryPool(const VulkanContext& ctx, VkQueryType type, uint32_t count,
                                    Cleanup& cleanup) {
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = type;
  info.queryCount = count;
  VkQueryPool pool = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(
      vkCheck(vkCreateQueryPool(ctx.device, &info, nullptr, &pool), "vkCreateQueryPool"));
  VkDevice device = ctx.device;
  cleanup.add([device, pool] { vkDestroyQueryPool(device, pool, nullptr); });
  return pool;
}

// The pool's results as 64-bit words, `words` per query.
Result<std::vector<uint64_t>> poolResults(const VulkanContext& ctx, VkQueryPool pool,
                                          uint32_t count, uint32_t words,
                                          VkQueryResultFlags flags) {
  std::vector<uint64_t> out(size_t(count) * words);
  const VkDeviceSize stride = words * sizeof(uint64_t);
  RAYSPEC_TRY_VOID(
      vkCheck(vkGetQueryPoolResults(ctx.device, pool, 0, count, count * stride, out.data(), stride,
                                    flags | VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
              "vkGetQueryPoolResults"));
  return out;
}

// The host form: vkWriteAccelerationStructuresPropertiesKHR
// (accelerationStructureHostCommands; the structures in host-visible memory).
Result<QueriedValues> hostProperty(const VulkanContext& ctx,
                                   const std::vector<VkAccelerationStructureKHR>& handles,
                                   VkQueryType type) {
  QueriedValues read;
  read.values.resize(handles.size());
  RAYSPEC_TRY_VOID(
      vkCheck(ctx.fn.writeAccelerationStructuresProperties(
                  ctx.device, static_cast<uint32_t>(handles.size()), handles.data(), type,
                  read.values.size() * sizeof(uint64_t), read.values.data(), sizeof(uint64_t)),
              "vkWriteAccelerationStructuresPropertiesKHR"));
  return read;
}

std::string sizeText(uint64_t v) {
  return std::to_string(v) + " bytes";
}

}  // namespace

Result<QueriedValues> queryProperty(const VulkanContext& ctx,
                                    const std::vector<VkAccelerationStructureKHR>& handles,
                                    VkQueryType type, Cleanup& cleanup) {
  const uint32_t count = static_cast<uint32_t>(handles.size());
  RAYSPEC_TRY(const VkQueryPool pool, createQueryPool(ctx, type, count, cleanup));
  RAYSPEC_TRY(VkCommandBuffer cmd, beginCommands(ctx, cleanup));
  vkCmdResetQueryPool(cmd, pool, 0, count);
  ctx.fn.cmdWriteAccelerationStructuresProperties(cmd, count, handles.data(), type, pool, 0);
  RAYSPEC_TRY_VOID(submitAndWait(ctx, cmd));
  QueriedValues read;
  RAYSPEC_TRY(read.values, poolResults(ctx, pool, count, 1, 0));
  RAYSPEC_TRY(const std::vector<uint64_t> pairs,
              poolResults(ctx, pool, count, 2, VK_QUERY_RESULT_WITH_AVAILABILITY_BIT));
  for (uint32_t i = 0; i < count; ++i) {
    read.with_availability.push_back(pairs[2 * i]);
    read.availability.push_back(pairs[2 * i + 1]);
  }
  return read;
}

namespace {

// What one level's checks share: the level, the fault, where findings go.
class LevelChecks {
 public:
  LevelChecks(const VulkanContext& ctx, const QueriedLevel& level, LayoutFault fault,
              std::vector<DeviceFinding>& findings)
      : ctx_(ctx), level_(level), fault_(fault), findings_(findings) {}

  // One query of every structure, its answers as the fault leaves them.
  Result<QueriedValues> ask(StructureQuery q, QueryCommand command, Cleanup& cleanup) const {
    const std::vector<VkAccelerationStructureKHR> handles = handlesOf(level_.structures);
    RAYSPEC_TRY(QueriedValues read, command == QueryCommand::Host
                                        ? hostProperty(ctx_, handles, vkQueryType(q))
                                        : queryProperty(ctx_, handles, vkQueryType(q), cleanup));
    plant(q, read);
    return read;
  }

  // R-AS-QUERY-AVAILABILITY: read after the wait, each query available, its
  // value as read without the availability word.
  void checkAvailability(StructureQuery q, const QueriedValues& read) {
    for (size_t i = 0; i < read.availability.size(); ++i) {
      const std::string what = name(i) + ", query " + nameOf(q) + ": ";
      if (read.availability[i] == 0)
        add("R-AS-QUERY-AVAILABILITY",
            what +
                "the availability word read with VK_QUERY_RESULT_WITH_AVAILABILITY_BIT after "
                "VK_QUERY_RESULT_WAIT_BIT is 0");
      if (read.with_availability[i] != read.values[i])
        add("R-AS-QUERY-AVAILABILITY", what + "value " + std::to_string(read.with_availability[i]) +
                                           " read with the availability word, " +
                                           std::to_string(read.values[i]) + " without");
    }
  }

  // R-AS-QUERY-COMPACTED, R-AS-QUERY-SIZE: nonzero, at most the size the
  // structure was created with.
  void checkAtMostCreated(StructureQuery q, const QueriedValues& read) {
    const char* rule =
        q == StructureQuery::CompactedSize ? "R-AS-QUERY-COMPACTED" : "R-AS-QUERY-SIZE";
    for (size_t i = 0; i < read.values.size(); ++i) {
      const uint64_t created = level_.structures[i].size;
      const std::string what = name(i) + ", query " + nameOf(q) + ": ";
      if (read.values[i] == 0)
        add(rule, what + "0 bytes (a structure needs some)");
      else if (read.values[i] > created)
        add(rule, what + sizeText(read.values[i]) + ", more than the " + sizeText(created) +
                      " it was created with (its build's accelerationStructureSize)");
    }
  }

  // R-AS-SERIAL-HEADER of structure i's serialized copy.
  void checkHeader(const SerializedCopies& s, size_t i, uint64_t queried_size) {
    SerializedHeader h = s.header(i);
    if (fault_ == LayoutFault::UuidWrong) h.driver_uuid[0] ^= 0xff;
    const std::string what = name(i) + " serialized, header ";
    const std::string uuid = hexBytes(h.driver_uuid.data(), VK_UUID_SIZE);
    if (!deviceDriverUuid().empty() && uuid != deviceDriverUuid())
      add("R-AS-SERIAL-HEADER", what + "driverUUID " + uuid +
                                    ", the device's VkPhysicalDeviceIDProperties::driverUUID " +
                                    deviceDriverUuid());
    std::vector<uint8_t> version(s.data(i), s.data(i) + 2 * VK_UUID_SIZE);
    std::memcpy(version.data(), h.driver_uuid.data(), VK_UUID_SIZE);
    if (!deviceCallsCompatible(ctx_, version.data()))
      add("R-AS-SERIAL-HEADER",
          what +
              "UUIDs: vkGetDeviceAccelerationStructureCompatibilityKHR calls the device's own "
              "serialized structure incompatible");
    if (h.serialized_size != queried_size)
      add("R-AS-SERIAL-HEADER", what + "serialized size " + sizeText(h.serialized_size) +
                                    ", the serialization size query " + sizeText(queried_size));
  }

  // R-AS-SERIAL-POINTERS of top level i's serialized copy: its handle count
  // that of the pointers query (when asked), each handle a referenced BLAS's.
  void checkPointers(const SerializedCopies& s, size_t i, const uint64_t* queried_count) {
    const uint8_t* d = s.data(i);
    uint64_t count = 0;
    std::memcpy(&count, d + kHandleCountOffset, 8);
    const std::string what = name(i) + " serialized, header ";
    if (queried_count && count != *queried_count)
      add("R-AS-SERIAL-POINTERS", what + "handle count " + std::to_string(count) +
                                      ", the bottom-level pointers query " +
                                      std::to_string(*queried_count));
    if (s.sizes[i] < kHandleCountOffset + 8 || count > (s.sizes[i] - kHandleCountOffset - 8) / 8) {
      add("R-AS-SERIAL-POINTERS", what + "handle count " + std::to_string(count) +
                                      ": more handles than its " + sizeText(s.sizes[i]) + " hold");
      return;
    }
    for (uint64_t k = 0; k < count; ++k) {
      VkDeviceAddress handle = 0;
      std::memcpy(&handle, d + kHandleCountOffset + 8 + 8 * k, 8);
      if (level_.referenced[i].count(handle) == 0)
        add("R-AS-SERIAL-POINTERS", what + "handle " + std::to_string(k) + " (" +
                                        hexBytes(&handle, 8) +
                                        ") is no device address of a bottom level its instances "
                                        "reference");
    }
  }

 private:
  // The answers a device with the planted fault gives: a size past the
  // structure's, one pointer more, no availability.
  void plant(StructureQuery q, QueriedValues& read) const {
    const bool too_large =
        (fault_ == LayoutFault::CompactedTooLarge && q == StructureQuery::CompactedSize) ||
        (fault_ == LayoutFault::SizeTooLarge && q == StructureQuery::Size);
    const bool one_more =
        fault_ == LayoutFault::PointerCountOff && q == StructureQuery::BottomLevelPointers;
    for (std::vector<uint64_t>* v : {&read.values, &read.with_availability})
      for (size_t i = 0; i < v->size(); ++i) {
        if (too_large) (*v)[i] = level_.structures[i].size + 256;
        if (one_more) (*v)[i] += 1;
      }
    if (fault_ == LayoutFault::AvailabilityLost)
      for (uint64_t& a : read.availability) a = 0;
  }

  // The driverUUID part of DeviceInfo::device_uuid ("deviceUUID-driverUUID").
  std::string deviceDriverUuid() const {
    const std::string& both = ctx_.info.device_uuid;
    const size_t dash = both.find('-');
    return dash == std::string::npos ? std::string() : both.substr(dash + 1);
  }
  const std::string& name(size_t i) const { return level_.structures[i].name; }
  void add(const char* rule, const std::string& message) { findings_.push_back({rule, message}); }

  const VulkanContext& ctx_;
  const QueriedLevel& level_;
  const LayoutFault fault_;
  std::vector<DeviceFinding>& findings_;
};

}  // namespace

Result<void> checkStructureQueries(const VulkanContext& ctx, const StructureQueries& asked,
                                   const QueriedLevel& level, LayoutFault fault,
                                   MemoryGuards& guards, Cleanup& cleanup,
                                   std::vector<DeviceFinding>& findings) {
  if (level.structures.empty()) return {};
  LevelChecks checks(ctx, level, fault, findings);
  std::vector<uint64_t> serialization_sizes, pointer_counts;
  for (StructureQuery q : asked.queries) {
    if (q == StructureQuery::BottomLevelPointers && !level.top) continue;  // VUID-...-12425
    RAYSPEC_TRY(const QueriedValues read, checks.ask(q, asked.command, cleanup));
    checks.checkAvailability(q, read);
    if (q == StructureQuery::CompactedSize || q == StructureQuery::Size)
      checks.checkAtMostCreated(q, read);
    if (q == StructureQuery::SerializationSize) serialization_sizes = read.values;
    if (q == StructureQuery::BottomLevelPointers) pointer_counts = read.values;
  }
  if (serialization_sizes.empty() && pointer_counts.empty()) return {};
  RAYSPEC_TRY(const SerializedCopies s, serializeToHost(ctx, level.structures, guards, cleanup));
  for (size_t i = 0; i < level.structures.size(); ++i) {
    checks.checkHeader(s, i, serialization_sizes.empty() ? s.sizes[i] : serialization_sizes[i]);
    if (level.top)
      checks.checkPointers(s, i, pointer_counts.empty() ? nullptr : &pointer_counts[i]);
  }
  return {};
}

}  // namespace rayspec
