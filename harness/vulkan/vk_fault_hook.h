// The Vulkan side's fault-injection hook (test only). The planted faults
// device-lost, out-of-device-memory and pipeline-refused (vulkan/
// device_errors.h) make one Vulkan call fail on purpose; they reach the
// Vulkan side through injectVkError and nothing else, and vkCall
// (vulkan/vk_check.h) is the one place that obeys it. A product run never
// sets it. README "The fault seam" lists every such hook.
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <string>

namespace rayspec {

struct InjectedVkError {
  std::string call;  // the Vulkan function whose calls fail ("" none)
  VkResult result = VK_SUCCESS;
};

// Every later call of e.call in this process is not made and answers
// e.result, until cleared (injectVkError({})).
void injectVkError(const InjectedVkError& e);

// The answer that stands for a call of `call`; none: make the call.
std::optional<VkResult> injectedVkError(const char* call);

}  // namespace rayspec
