#include <cstdio>

#include "cli/commands.h"
#include "vulkan/vulkan_backend.h"

namespace rayspec {

int runDevices(const DevicesOptions&) {
  std::string error;
  const std::vector<DeviceInfo> devices = listDevices(&error);
  if (!error.empty()) {
    std::fprintf(stderr, "rayspec devices: %s\n", error.c_str());
    return 1;
  }
  if (devices.empty()) std::printf("No Vulkan devices.\n");
  for (const DeviceInfo& d : devices) {
    std::printf("[%u] %s (driver %s %s, Vulkan %s)\n", d.index, d.name.c_str(), d.driver_name.c_str(),
                d.driver_info.c_str(), d.api_version.c_str());
    if (!d.ray_tracing_pipeline) {
      std::printf("    no VK_KHR_ray_tracing_pipeline\n");
      continue;
    }
    std::printf("    VK_KHR_ray_tracing_pipeline: yes   VK_KHR_acceleration_structure: %s\n",
                d.acceleration_structure ? "yes" : "no");
    std::printf("    shaderGroupHandleSize          %u\n", d.shader_group_handle_size);
    std::printf("    shaderGroupHandleAlignment     %u\n", d.shader_group_handle_alignment);
    std::printf("    shaderGroupBaseAlignment       %u\n", d.shader_group_base_alignment);
    std::printf("    maxRayRecursionDepth           %u\n", d.max_ray_recursion_depth);
    std::printf("    maxRayHitAttributeSize         %u\n", d.max_ray_hit_attribute_size);
    std::printf("    maxShaderGroupStride           %u\n", d.max_shader_group_stride);
    std::printf("    maxRayDispatchInvocationCount  %u\n", d.max_ray_dispatch_invocation_count);
    std::printf("    accelerationStructureHostCommands %s\n", d.acceleration_structure_host_commands ? "yes" : "no");
  }
  return 0;
}

}  // namespace rayspec
