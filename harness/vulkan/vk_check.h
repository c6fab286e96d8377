// VkResult names and the internal error types the backend throws; run()
// turns them into a status ("Crash: ..." / "NotSupported: ..."), so nothing
// escapes the backend.
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "vulkan/vk_fault_hook.h"

namespace rayspec {

const char* vkResultName(VkResult r);

// A Vulkan call failed: what = "<call>: <VkResult name>".
struct VulkanError : std::runtime_error {
  VulkanError(const std::string& what, std::string call = {}, VkResult result = VK_ERROR_UNKNOWN)
      : std::runtime_error(what), call(std::move(call)), result(result) {}
  std::string call;  // the Vulkan function, when a call failed
  VkResult result;
};

// The device cannot run the case (a limit or a feature it lacks).
struct NotSupportedError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws VulkanError unless r == VK_SUCCESS.
void vkCheck(VkResult r, const char* what);

// vkCheck(make(), what), unless an injected error stands for the call.
template <typename F>
void vkCall(const char* what, F make) {
  const std::optional<VkResult> injected = injectedVkError(what);  // test only: the fault seam
  vkCheck(injected ? *injected : make(), what);
}

}  // namespace rayspec
