// The name of a VkDriverId, as vulkan.hpp spells it (MesaLlvmpipe,
// NvidiaProprietary), with its number: `rayspec devices` prints it.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace rayspec {

// "MesaLlvmpipe (13)"; an id this Vulkan header does not know: "unknown (N)".
std::string driverIdName(VkDriverId id);

}  // namespace rayspec
