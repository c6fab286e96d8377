// Whether a device can run a case, from what rayspec knows of it (DeviceInfo)
// alone: the features, extensions and limits the case needs, each missing one
// a NotSupported error that names it. The one decision: VulkanEngine runs it
// before building anything (vulkan/run_case.h), the run's parent before
// either side of a case runs (run/case_steps.h), `rayspec devices` over the
// library to count the cases each missing feature skips.
#pragma once

#include <cstdint>

#include "base/result.h"
#include "case/case.h"
#include "plan/plan.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {

// validation_layer: the Khronos validation layer's specVersion while it is
// on, 0 while it is off. A layer older than an extension reports the SPIR-V
// that uses it as an error, so a case that needs one (vertex_position<i>:
// VK_KHR_ray_tracing_position_fetch, 1.3.249) is NotSupported under it.
Result<void> checkCaseSupport(const DeviceInfo& d, uint32_t validation_layer, const Case& c,
                              const Plan& plan);

// The device feature a sized type's values need (int8 .. f64vec4: shaderInt8,
// shaderInt16, shaderInt64, shaderFloat16, shaderFloat64, as the feature
// column of program/sized_types.h names it; a vector's is its component's),
// or null for one that needs none (int32, uint's vectors) and every other type.
bool DeviceInfo::*sizedTypeFeature(ValueType t);

// Whether a feature of the Vulkan header version `since` may be enabled under
// that layer: no layer is on (0), or it knows the feature.
bool validationLayerKnows(uint32_t validation_layer, uint32_t since);

// The device side's first step on a case (runCase), before it builds
// anything: a case only compiled, never launched (expected_rejections), runs
// on any device; any other case as checkCaseSupport says. The run's parent
// asks it of the probed device, so that a case the device cannot run costs
// no model time (run/case_steps.h).
Result<void> checkCaseRuns(const DeviceInfo& d, uint32_t validation_layer, const Case& c,
                           const Plan& plan);

}  // namespace rayspec
