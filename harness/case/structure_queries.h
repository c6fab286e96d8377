// scene.build.queries: the properties of every structure a case asks the
// device for (vkCmdWriteAccelerationStructuresPropertiesKHR into a query
// pool, or vkWriteAccelerationStructuresPropertiesKHR on the host), each
// held to what the specification guarantees (R-AS-QUERY-*, R-AS-SERIAL-*;
// vulkan/structure_queries.h), and the bottom levels each top level's
// instances reference, which a serialized top level's header may list.
#pragma once

#include <cstdint>
#include <set>
#include <vector>

#include "base/enum_names.h"

namespace rayspec {

struct Scene;

// compacted_size: VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR
// (every build gets ALLOW_COMPACTION); serialization_size: ..._SERIALIZATION_SIZE_KHR
// (the structures are serialized too, their headers checked); size and
// bottom_level_pointers: VK_KHR_ray_tracing_maintenance1's ..._SIZE_KHR and
// ..._SERIALIZATION_BOTTOM_LEVEL_POINTERS_KHR (the latter of top levels only).
#define RAYSPEC_STRUCTURE_QUERIES(X)         \
  X(CompactedSize, "compacted_size")         \
  X(SerializationSize, "serialization_size") \
  X(Size, "size") X(BottomLevelPointers, "bottom_level_pointers")
enum class StructureQuery { RAYSPEC_STRUCTURE_QUERIES(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(StructureQuery, RAYSPEC_STRUCTURE_QUERIES);

// scene.build.query_command: device (a query pool, read with and without
// VK_QUERY_RESULT_WITH_AVAILABILITY_BIT) or host (accelerationStructureHostCommands).
#define RAYSPEC_QUERY_COMMANDS(X) X(Device, "device") X(Host, "host")
enum class QueryCommand { RAYSPEC_QUERY_COMMANDS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(QueryCommand, RAYSPEC_QUERY_COMMANDS);

struct StructureQueries {
  std::vector<StructureQuery> queries;  // in the case's order, each once
  QueryCommand command = QueryCommand::Device;
  bool asks(StructureQuery q) const;
  // Whether a query needs VK_KHR_ray_tracing_maintenance1.
  bool needsMaintenance1() const;
};

// Per top level (Scene::tlasCount()): the indices of the bottom levels its
// active instances reference. A serialized top level's header lists
// handles of these and no others (R-AS-SERIAL-POINTERS).
std::vector<std::set<uint32_t>> referencedBlases(const Scene& scene);

}  // namespace rayspec
