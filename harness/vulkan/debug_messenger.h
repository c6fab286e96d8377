// Captures validation-layer messages (VK_EXT_debug_utils). Messages of
// severity ERROR are kept until taken; run() takes them per case.
#pragma once

#include <vulkan/vulkan.h>

#include <mutex>
#include <string>
#include <vector>

#include "base/result.h"

namespace rayspec {

class DebugCapture {
 public:
  void add(std::string message);
  std::vector<std::string> take();  // returns and clears the kept errors

  // Fills a create info whose callback feeds this capture (for
  // vkCreateDebugUtilsMessengerEXT and for VkInstanceCreateInfo::pNext).
  VkDebugUtilsMessengerCreateInfoEXT createInfo();

 private:
  std::mutex mutex_;
  std::vector<std::string> errors_;
};

// A messenger feeding `capture`, or the Device error.
Result<VkDebugUtilsMessengerEXT> createDebugMessenger(VkInstance instance, DebugCapture* capture);
void destroyDebugMessenger(VkInstance instance, VkDebugUtilsMessengerEXT messenger);

}  // namespace rayspec
