// VkResult names and the internal error types the backend throws; run()
// turns them into a status ("Crash: ..." / "NotSupported: ..."), so nothing
// escapes the backend.
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace rayspec {

const char* vkResultName(VkResult r);

// A Vulkan call failed: what = "<call>: <VkResult name>".
struct VulkanError : std::runtime_error {
  VulkanError(const std::string& what, std::string call_ = {}, VkResult result_ = VK_ERROR_UNKNOWN)
      : std::runtime_error(what), call(std::move(call_)), result(result_) {}
  std::string call;  // the Vulkan function, when a call failed
  VkResult result;
};

// The device cannot run the case (a limit or a feature it lacks).
struct NotSupportedError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws VulkanError unless r == VK_SUCCESS.
void vkCheck(VkResult r, const char* what);

// Test only (the planted faults device-lost, out-of-device-memory,
// pipeline-refused): every later call of `call` in this process is not made
// and returns `result`, until cleared (empty call). vkCall below obeys it.
struct InjectedVkError {
  std::string call;
  VkResult result = VK_SUCCESS;
};
void injectVkError(const InjectedVkError& e);
bool injectedVkError(const char* call,
                     VkResult* result);  // true: do not call, *result is the answer

// vkCheck(make(), what), unless an injected error stands for the call.
template <typename F>
void vkCall(const char* what, F make) {
  VkResult r;
  if (!injectedVkError(what, &r)) r = make();
  vkCheck(r, what);
}

}  // namespace rayspec
