// A built acceleration structure as builds and copies hand it on.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace rayspec {

// The handle, the size it was created with, and what the guards call it
// ("BLAS 2", "TLAS 0").
struct BuiltStructure {
  VkAccelerationStructureKHR handle = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
  std::string name;
};

}  // namespace rayspec
