// The pipeline stack size a case sets (pipeline.callable_depth, R-STACK):
// every shader's stack size from vkGetRayTracingShaderGroupStackSizeKHR, and
// the specification's formula ("Ray Tracing Pipeline Stack") with the case's
// callable depth in place of its two callable frames. The trace sets it with
// vkCmdSetRayTracingPipelineStackSizeKHR (trace.cpp).
#pragma once

#include <vulkan/vulkan.h>

#include "vulkan/context.h"
#include "vulkan/pipeline.h"

namespace rayspec {

// The largest stack size of each kind of shader in the pipeline, bytes.
struct ShaderStackSizes {
  VkDeviceSize raygen = 0, miss = 0, closest_hit = 0, any_hit = 0, intersection = 0, callable = 0;
};

// raygen + min(1, R) x max(closest-hit, miss, intersection + any-hit)
//        + max(0, R - 1) x max(closest-hit, miss) + callable_depth x callable
// with R = max_recursion (a pure computation, unit-tested).
VkDeviceSize pipelineStackSize(const ShaderStackSizes& s, uint32_t max_recursion,
                               uint32_t callable_depth);

// Every shader of every group of the linked pipeline, by kind (the query
// cannot fail: it answers a size).
ShaderStackSizes queryShaderStackSizes(const VulkanContext& ctx, const CompiledPipeline& compiled,
                                       const Pipeline& p, const RayTracingPipeline& pipeline);

}  // namespace rayspec
