#include "vulkan/debug_messenger.h"

#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                         VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data,
                                         void* user) {
  if ((severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) && data && user) {
    std::string text;
    if (data->pMessageIdName) text = std::string(data->pMessageIdName) + ": ";
    if (data->pMessage) text += data->pMessage;
    static_cast<DebugCapture*>(user)->add(std::move(text));
  }
  return VK_FALSE;  // never abort the call
}

}  // namespace

void DebugCapture::add(std::string message) {
  std::lock_guard<std::mutex> lock(mutex_);
  errors_.push_back(std::move(message));
}

std::vector<std::string> DebugCapture::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> out;
  out.swap(errors_);
  return out;
}

VkDebugUtilsMessengerCreateInfoEXT DebugCapture::createInfo() {
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = onMessage;
  info.pUserData = this;
  return info;
}

Result<VkDebugUtilsMessengerEXT> createDebugMessenger(VkInstance instance, DebugCapture* capture) {
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
  if (!create) return deviceError("vkGetInstanceProcAddr(vkCreateDebugUtilsMessengerEXT): missing");
  VkDebugUtilsMessengerCreateInfoEXT info = capture->createInfo();
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(
      vkCheck(create(instance, &info, nullptr, &messenger), "vkCreateDebugUtilsMessengerEXT"));
  return messenger;
}

void destroyDebugMessenger(VkInstance instance, VkDebugUtilsMessengerEXT messenger) {
  if (!messenger) return;
  auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
  if (destroy) destroy(instance, messenger, nullptr);
}

}  // namespace rayspec
