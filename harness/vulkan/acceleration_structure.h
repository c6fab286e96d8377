// Bottom- and top-level acceleration structures, built on the device through
// a command buffer (lavapipe has no host commands).
#pragma once

#include <vulkan/vulkan.h>

#include "case/case.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"

namespace rayspec {

// Records into cmd: one BLAS build per case Blas that some instance references
// (all in one vkCmdBuildAccelerationStructuresKHR), a barrier, the TLAS build
// (an instance with a null BLAS gets accelerationStructureReference 0), and a
// barrier making the TLAS readable by ray tracing shaders. Buffers and
// structures live until cleanup runs. One TLAS per top level
// (Scene::tlasCount()), each over all instances in order, those of the
// other levels with reference 0. Returns them by level.
std::vector<VkAccelerationStructureKHR> recordSceneBuild(const VulkanContext& ctx,
                                                         const Scene& scene, VkCommandBuffer cmd,
                                                         Cleanup& cleanup);

}  // namespace rayspec
