#include "vulkan/driver_id_name.h"

#include <vulkan/vulkan.hpp>

namespace rayspec {

std::string driverIdName(VkDriverId id) {
  std::string name = vk::to_string(static_cast<vk::DriverId>(id));
  if (name.rfind("invalid", 0) == 0) name = "unknown";
  return name + " (" + std::to_string(static_cast<int>(id)) + ")";
}

}  // namespace rayspec
