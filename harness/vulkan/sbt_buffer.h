// The shader binding table on the device: sbt_layout.h's bytes in a host
// buffer whose used part starts at a shaderGroupBaseAlignment address.
#pragma once

#include <vulkan/vulkan.h>

#include "case/case.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"
#include "vulkan/pipeline.h"
#include "vulkan/sbt_layout.h"

namespace rayspec {

SbtLimits deviceSbtLimits(const VulkanContext& ctx);

struct SbtBuffer {
  SbtLayout layout;
  VkDeviceAddress base = 0;  // device address of the table (base-aligned)
};

// The NotSupported error for a layout the device's limits refuse (run_case
// checks that before building anything), a Device error for a bad record.
Result<SbtBuffer> createSbtBuffer(const VulkanContext& ctx, const Pipeline& p,
                                  const RayTracingPipeline& pipeline, Cleanup& cleanup);

}  // namespace rayspec
