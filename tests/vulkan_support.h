// Shared by the device tests of the Vulkan backend: whether this machine has
// a device to run them on.
#pragma once

#include <string>

#include "result_support.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {

inline bool rayTracingDeviceExists() {
  std::string error;
  for (const DeviceInfo& d : orError(listDevices(), &error))
    if (d.ray_tracing_pipeline && d.acceleration_structure) return true;
  return false;
}

}  // namespace rayspec
