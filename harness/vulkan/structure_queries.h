// Queries of acceleration structure properties (scene.build.queries,
// case/structure_queries.h): vkCmdWriteAccelerationStructuresPropertiesKHR
// into a query pool, read with and without
// VK_QUERY_RESULT_WITH_AVAILABILITY_BIT, or vkWriteAccelerationStructuresPropertiesKHR
// on the host; each answer held to what the specification guarantees, a
// broken guarantee a finding of its rule naming the structure and the field:
//   R-AS-QUERY-COMPACTED   a compacted size is nonzero and at most the size
//                          the structure was created with (its build's
//                          accelerationStructureSize)
//   R-AS-QUERY-SIZE        the size query (VK_KHR_ray_tracing_maintenance1)
//                          likewise
//   R-AS-QUERY-AVAILABILITY  read after VK_QUERY_RESULT_WAIT_BIT, every
//                          query is available, its value the same as read
//                          without the availability word
//   R-AS-SERIAL-HEADER     a serialized structure's header: driverUUID the
//                          device's, the device calls it compatible
//                          (vkGetDeviceAccelerationStructureCompatibilityKHR),
//                          its size the serialization size query's
//   R-AS-SERIAL-POINTERS   a serialized top level's handle count is the
//                          bottom-level pointers query's, each handle the
//                          device address of a bottom level its instances
//                          reference
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "case/structure_queries.h"
#include "results/results.h"
#include "vulkan/built_structure.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/memory_guards.h"
#include "vulkan/vk_fault_hook.h"

namespace rayspec {

// The query type of a scene.build.queries entry.
VkQueryType vkQueryType(StructureQuery q);

// One query type's answers, one per structure: as read without the
// availability word, and (the command form) as read with it, with that word.
struct QueriedValues {
  std::vector<uint64_t> values, with_availability, availability;
};

// The command form: one query pool, vkCmdWriteAccelerationStructuresPropertiesKHR,
// waited on, read twice. Or the Device error.
Result<QueriedValues> queryProperty(const VulkanContext& ctx,
                                    const std::vector<VkAccelerationStructureKHR>& handles,
                                    VkQueryType type, Cleanup& cleanup);

// The structures of one level, built and complete, and for a top level the
// device addresses of the bottom levels each one's instances reference.
struct QueriedLevel {
  std::vector<BuiltStructure> structures;
  bool top = false;
  std::vector<std::set<VkDeviceAddress>> referenced;  // per structure (top levels)
};

// Every query `asked` names, of every structure of `level`, each answer
// checked; each broken guarantee a line of `findings` (R-AS-QUERY-*,
// R-AS-SERIAL-*). Serialized copies are guarded (R-AS-MEMORY). `fault`: the
// answers a device with that planted query fault gives (vk_fault_hook.h; a
// product run passes None, and the other layout faults change nothing
// here). Or the Device error.
Result<void> checkStructureQueries(const VulkanContext& ctx, const StructureQueries& asked,
                                   const QueriedLevel& level, LayoutFault fault,
                                   MemoryGuards& guards, Cleanup& cleanup,
                                   std::vector<DeviceFinding>& findings);

}  // namespace rayspec
