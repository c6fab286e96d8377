// One case on the device, from the generated GLSL to the read-back Results.
#pragma once

#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"
#include "vulkan/context.h"

namespace rayspec {

// The NotSupported error when the device's limits or features cannot run
// the case (recursion depth, launch size, dispatch size, primitive culling,
// the SBT's strides), before anything is built.
Result<void> checkCaseSupport(const VulkanContext& ctx, const Case& c, const Plan& plan);
// checkCaseRuns (vulkan/case_support.h) of this device under its layer.
Result<void> checkCaseRuns(const VulkanContext& ctx, const Case& c, const Plan& plan);

// Fills r's outputs, or returns a ShaderCompile, NotSupported or Device
// error (VulkanEngine::run turns it into the status). Every object it
// creates is destroyed before it returns, on every path (its Cleanup).
Result<void> runCase(const VulkanContext& ctx, const Case& c, const Plan& plan, Results& r);

}  // namespace rayspec
