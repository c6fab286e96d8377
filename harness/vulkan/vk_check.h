// VkResult names and the Errors of the Vulkan backend (base/error.h): a
// failed call is an ErrorKind::Device error naming the call and its VkResult;
// a device that cannot run a case gives ErrorKind::NotSupported. VulkanEngine::run
// turns them into a status ("Crash: ..." / "NotSupported: ...").
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <string>

#include "base/result.h"
#include "vulkan/vk_fault_hook.h"

namespace rayspec {

const char* vkResultName(VkResult r);

// An ErrorKind::Device error: `message`, and the call that failed ("" when
// the error is no one call's) with its result.
Error deviceError(std::string message, std::string call = {}, VkResult result = VK_ERROR_UNKNOWN);

// An ErrorKind::NotSupported error: the device cannot run the case (a limit
// or a feature it lacks).
Error notSupported(std::string message);

// The Device error "<what>: <VkResult name>" unless r == VK_SUCCESS.
Result<void> vkCheck(VkResult r, const char* what);

// make()'s answer, unless an injected error stands for the call (then the
// call is not made).
template <typename F>
VkResult vkAnswer(const char* what, F make) {
  const std::optional<VkResult> injected = injectedVkError(what);  // test only: the fault seam
  return injected ? *injected : make();
}

// vkCheck(make(), what), unless an injected error stands for the call.
template <typename F>
Result<void> vkCall(const char* what, F make) {
  return vkCheck(vkAnswer(what, make), what);
}

}  // namespace rayspec
