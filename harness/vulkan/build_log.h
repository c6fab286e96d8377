// What a scene's builds made, as tests observe it (test only: a product run
// records nothing): each structure's create type, its level and where it lies
// in its buffer, the type each build named, and how each sparse buffer was
// bound. The tests of scene.build.generic and scene.build.sparse read it
// (tests/vulkan_structure_memory_test.cpp).
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

namespace rayspec {

struct LoggedStructure {
  VkAccelerationStructureKHR handle = VK_NULL_HANDLE;
  VkAccelerationStructureTypeKHR created,
      level;                          // VkAccelerationStructureCreateInfoKHR::type; real
  VkDeviceSize offset = 0, size = 0;  // in its buffer
  VkDeviceSize page = 0;              // its sparse buffer's page size; 0: bound whole
  VkBuffer buffer = VK_NULL_HANDLE;
};

struct LoggedBuild {
  VkAccelerationStructureKHR dst = VK_NULL_HANDLE;
  VkAccelerationStructureTypeKHR type;  // VkAccelerationStructureBuildGeometryInfoKHR::type
};

struct LoggedSparseBuffer {
  VkBufferCreateFlags flags = 0;
  VkDeviceSize size = 0, page = 0;  // the buffer's memory requirements: size, alignment
  uint32_t binds = 0;               // VkSparseMemoryBinds of its vkQueueBindSparse
  uint32_t allocations = 0;         // VkDeviceMemory objects its pages lie in
  bool in_order = true;             // each page at the memory offset after the one before's
};

struct BuildLog {
  std::vector<LoggedStructure> structures;
  std::vector<LoggedBuild> builds;
  std::vector<LoggedSparseBuffer> sparse;
};

// on: the log cleared and recording from now; off: no longer recording.
void recordBuildLog(bool on);
// The log while recording, else nullptr.
BuildLog* buildLog();

}  // namespace rayspec
