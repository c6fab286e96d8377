// VkResult names and the internal error types the backend throws; run()
// turns them into a status ("Crash: ..." / "NotSupported: ..."), so nothing
// escapes the backend.
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace rayspec {

const char* vkResultName(VkResult r);

// A Vulkan call failed: what = "<call>: <VkResult name>".
struct VulkanError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The device cannot run the case (a limit or a feature it lacks).
struct NotSupportedError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws VulkanError unless r == VK_SUCCESS.
void vkCheck(VkResult r, const char* what);

}  // namespace rayspec
