// Which driver library a VkDevice's commands live in. The loader hands out a
// device's commands straight from the top of its chain: the driver's own
// functions when no layer sits on the device, so dladdr on one names the
// driver's shared object. With the validation layer on, the top is the layer;
// a short-lived layer-free instance and device on the same physical device
// (by its index) answers instead.
#include <dlfcn.h>

#include <vector>

#include "vulkan/context.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

std::string libraryOf(VkDevice device) {
  const PFN_vkVoidFunction f = vkGetDeviceProcAddr(device, "vkQueueSubmit");
  Dl_info info{};
  if (!f || !dladdr(reinterpret_cast<void*>(f), &info) || !info.dli_fname) return {};
  return info.dli_fname;
}

// The library of device `index` of a new instance in `plain` (which the
// caller destroys); "" when there is no such device.
Result<std::string> libraryOfIndex(VulkanContext& plain, uint32_t index) {
  RAYSPEC_TRY_VOID(createInstance(plain, false));
  RAYSPEC_TRY(const std::vector<VkPhysicalDevice> physicals, physicalDevices(plain.instance));
  if (index >= physicals.size()) return std::string();
  plain.physical = physicals[index];
  RAYSPEC_TRY_VOID(createDevice(plain));
  return libraryOf(plain.device);
}

std::string libraryWithoutLayers(uint32_t index) {
  VulkanContext plain;
  const Result<std::string> library = libraryOfIndex(plain, index);
  destroyDevice(plain);
  destroyInstance(plain);
  return library ? *library : std::string();  // unknown on an error
}

}  // namespace

std::string VulkanEngine::driverLibrary() const {
  if (!ctx_->device) return {};
  return ctx_->validation ? libraryWithoutLayers(ctx_->info.index) : libraryOf(ctx_->device);
}

}  // namespace rayspec
