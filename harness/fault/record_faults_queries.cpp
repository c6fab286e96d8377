// The faults of scene.build.queries (vulkan/structure_queries.h): each rule's
// finding planted in a perfect device's results, as the device side's check
// makes it (a proof the judge fails the case on it), and the live Vulkan
// faults that make a device answer the query wrong (vulkan/vk_fault_hook.h),
// which the device side's own checks must catch.
#include <initializer_list>
#include <string>
#include <vector>

#include "fault/fault_impl.h"

namespace rayspec {
namespace {

// The case asks for query q (or, serialized: any query that serializes).
std::string missingQuery(const Case& c, std::initializer_list<StructureQuery> any) {
  for (StructureQuery q : any)
    if (c.scene.build.queries.asks(q)) return "";
  std::string names;
  for (StructureQuery q : any) names += std::string(names.empty() ? "" : " or ") + nameOf(q);
  return "the case asks for no " + names + " query (scene.build.queries)";
}

FaultResult plantIfAsked(RecordFaultArgs& a, std::initializer_list<StructureQuery> any,
                         DeviceFinding finding, std::string what) {
  const std::string missing = missingQuery(a.c, any);
  if (!missing.empty()) return notApplicable(missing);
  return plantDeviceFinding(a, std::move(finding), std::move(what));
}

// Query q of `structure` answering 4352 bytes, more than the 4096 it was
// created with, as the device side's check words it.
FaultResult sizeReportedLarge(RecordFaultArgs& a, StructureQuery q, const char* rule,
                              const std::string& structure, std::string what) {
  return plantIfAsked(a, {q},
                      {rule, structure + ", query " + nameOf(q) +
                                 ": 4352 bytes, more than the 4096 bytes it was created with "
                                 "(its build's accelerationStructureSize) (planted)"},
                      std::move(what));
}

FaultResult compactedSizeReportedLarge(RecordFaultArgs& a) {
  return sizeReportedLarge(a, StructureQuery::CompactedSize, "R-AS-QUERY-COMPACTED", "BLAS 0",
                           "a compacted size larger than the structure");
}

FaultResult structureSizeReportedLarge(RecordFaultArgs& a) {
  return sizeReportedLarge(a, StructureQuery::Size, "R-AS-QUERY-SIZE", "TLAS 0",
                           "a structure size larger than the structure");
}

FaultResult queryUnavailable(RecordFaultArgs& a) {
  if (a.c.scene.build.queries.command != QueryCommand::Device)
    return notApplicable("the host form reads no availability (scene.build.query_command host)");
  const std::vector<StructureQuery>& asked = a.c.scene.build.queries.queries;
  if (asked.empty()) return notApplicable("the case asks for no query (scene.build.queries)");
  return plantDeviceFinding(
      a,
      {"R-AS-QUERY-AVAILABILITY",
       "BLAS 0, query " + std::string(nameOf(asked.front())) +
           ": the availability word read with VK_QUERY_RESULT_WITH_AVAILABILITY_BIT after "
           "VK_QUERY_RESULT_WAIT_BIT is 0 (planted)"},
      "a query unavailable after the wait");
}

FaultResult serializedHeaderWrong(RecordFaultArgs& a) {
  return plantIfAsked(
      a, {StructureQuery::SerializationSize, StructureQuery::BottomLevelPointers},
      {"R-AS-SERIAL-HEADER",
       "TLAS 0 serialized, header driverUUID 00000000000000000000000000000000, the device's "
       "VkPhysicalDeviceIDProperties::driverUUID another (planted)"},
      "a serialized header naming another driver");
}

FaultResult serializedPointerForeign(RecordFaultArgs& a) {
  return plantIfAsked(a, {StructureQuery::SerializationSize, StructureQuery::BottomLevelPointers},
                      {"R-AS-SERIAL-POINTERS",
                       "TLAS 0 serialized, header handle 0 (0000000000000000) is no device "
                       "address of a bottom level its instances reference (planted)"},
                      "a serialized top level listing a handle of no referenced bottom level");
}

}  // namespace

std::vector<FaultImpl> queryFaults() {
  using K = FaultKind;
  return {
      {"compacted-size-reported-large", K::RecordEdit,
       "a compacted size query answers more than the structure's size (the finding the device "
       "side's check makes; compacted-size-too-large makes it on a live device)",
       compactedSizeReportedLarge},
      {"structure-size-reported-large", K::RecordEdit,
       "a size query answers more than the structure's size (structure-size-too-large live)",
       structureSizeReportedLarge},
      {"query-unavailable", K::RecordEdit,
       "a query reads unavailable after VK_QUERY_RESULT_WAIT_BIT (query-availability-lost live)",
       queryUnavailable},
      {"serialized-header-wrong", K::RecordEdit,
       "a serialized structure's header names another driverUUID (serialized-uuid-wrong live)",
       serializedHeaderWrong},
      {"serialized-pointer-foreign", K::RecordEdit,
       "a serialized top level lists a handle of no bottom level its instances reference "
       "(pointer-count-off live)",
       serializedPointerForeign},
      {"compacted-size-too-large", K::Vulkan,
       "the compacted size query answers 256 bytes past the structure's size"},
      {"structure-size-too-large", K::Vulkan,
       "the size query answers 256 bytes past the structure's size"},
      {"query-availability-lost", K::Vulkan,
       "the queries read with VK_QUERY_RESULT_WITH_AVAILABILITY_BIT answer availability 0"},
      {"serialized-uuid-wrong", K::Vulkan,
       "a serialized structure's header carries a driverUUID with its first byte flipped"},
      {"pointer-count-off", K::Vulkan,
       "the bottom-level pointers query answers one more than the serialized header's count"},
  };
}

}  // namespace rayspec
