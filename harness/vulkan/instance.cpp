#include <algorithm>
#include <cstring>
#include <vector>

#include "vulkan/context.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// The layer's specVersion (the Vulkan header it was built with), 0 when it
// is not installed.
uint32_t layerVersion(const char* name) {
  uint32_t count = 0;
  if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return 0;
  std::vector<VkLayerProperties> layers(count);
  if (vkEnumerateInstanceLayerProperties(&count, layers.data()) != VK_SUCCESS) return 0;
  for (const VkLayerProperties& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return std::max<uint32_t>(1, l.specVersion);
  return 0;
}

bool hasInstanceExtension(const char* name, const char* layer) {
  uint32_t count = 0;
  if (vkEnumerateInstanceExtensionProperties(layer, &count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> exts(count);
  if (vkEnumerateInstanceExtensionProperties(layer, &count, exts.data()) != VK_SUCCESS)
    return false;
  for (const VkExtensionProperties& e : exts)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

}  // namespace

uint32_t installedValidationLayer() {
  return layerVersion(kValidationLayer);
}

uint32_t validationLayerFor(bool want) {
  const uint32_t version = want ? layerVersion(kValidationLayer) : 0;
  const bool messenger =
      version != 0 && (hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME, nullptr) ||
                       hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME, kValidationLayer));
  return messenger ? version : 0;
}

Result<void> createInstance(VulkanContext& ctx, bool want_validation) {
  const uint32_t layer_version = validationLayerFor(want_validation);
  ctx.validation = layer_version != 0;

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "rayspec";
  app.applicationVersion = VK_MAKE_API_VERSION(0, 0, 1, 0);
  app.pEngineName = "rayspec";
  app.apiVersion = VK_API_VERSION_1_3;

  std::vector<const char*> layers, extensions;
  VkDebugUtilsMessengerCreateInfoEXT messenger_info{};
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  if (ctx.validation) {
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    // Also catch messages of vkCreateInstance / vkDestroyInstance themselves.
    messenger_info = ctx.capture->createInfo();
    info.pNext = &messenger_info;
  }
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  RAYSPEC_TRY_VOID(vkCheck(vkCreateInstance(&info, nullptr, &ctx.instance), "vkCreateInstance"));
  if (ctx.validation) {
    RAYSPEC_TRY(ctx.messenger, createDebugMessenger(ctx.instance, ctx.capture.get()));
  }
  ctx.validation_layer_version = ctx.validation ? layer_version : 0;
  return {};
}

void destroyInstance(VulkanContext& ctx) {
  if (!ctx.instance) return;
  destroyDebugMessenger(ctx.instance, ctx.messenger);
  ctx.messenger = VK_NULL_HANDLE;
  vkDestroyInstance(ctx.instance, nullptr);
  ctx.instance = VK_NULL_HANDLE;
}

Result<std::vector<VkPhysicalDevice>> physicalDevices(VkInstance instance) {
  uint32_t count = 0;
  RAYSPEC_TRY_VOID(
      vkCheck(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices"));
  std::vector<VkPhysicalDevice> physicals(count);
  RAYSPEC_TRY_VOID(vkCheck(vkEnumeratePhysicalDevices(instance, &count, physicals.data()),
                           "vkEnumeratePhysicalDevices"));
  physicals.resize(count);
  return physicals;
}

}  // namespace rayspec
