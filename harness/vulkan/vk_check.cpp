#include "vulkan/vk_check.h"

namespace rayspec {

const char* vkResultName(VkResult r) {
  switch (r) {
#define RAYSPEC_CASE(x) \
  case x:               \
    return #x;
    RAYSPEC_CASE(VK_SUCCESS)
    RAYSPEC_CASE(VK_NOT_READY)
    RAYSPEC_CASE(VK_TIMEOUT)
    RAYSPEC_CASE(VK_EVENT_SET)
    RAYSPEC_CASE(VK_EVENT_RESET)
    RAYSPEC_CASE(VK_INCOMPLETE)
    RAYSPEC_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    RAYSPEC_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    RAYSPEC_CASE(VK_ERROR_INITIALIZATION_FAILED)
    RAYSPEC_CASE(VK_ERROR_DEVICE_LOST)
    RAYSPEC_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    RAYSPEC_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    RAYSPEC_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    RAYSPEC_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    RAYSPEC_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    RAYSPEC_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    RAYSPEC_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    RAYSPEC_CASE(VK_ERROR_FRAGMENTED_POOL)
    RAYSPEC_CASE(VK_ERROR_UNKNOWN)
    RAYSPEC_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    RAYSPEC_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    RAYSPEC_CASE(VK_ERROR_FRAGMENTATION)
    RAYSPEC_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    RAYSPEC_CASE(VK_PIPELINE_COMPILE_REQUIRED)
    RAYSPEC_CASE(VK_THREAD_IDLE_KHR)
    RAYSPEC_CASE(VK_THREAD_DONE_KHR)
    RAYSPEC_CASE(VK_OPERATION_DEFERRED_KHR)
    RAYSPEC_CASE(VK_OPERATION_NOT_DEFERRED_KHR)
    RAYSPEC_CASE(VK_ERROR_VALIDATION_FAILED_EXT)
    RAYSPEC_CASE(VK_ERROR_INVALID_SHADER_NV)
#undef RAYSPEC_CASE
    default:
      return "VK_ERROR_<unnamed>";
  }
}

Error deviceError(std::string message, std::string call, VkResult result) {
  Error e = errorOf(ErrorKind::Device, std::move(message));
  e.call = std::move(call);
  e.result = vkResultName(result);
  return e;
}

Error notSupported(std::string message) {
  return errorOf(ErrorKind::NotSupported, std::move(message));
}

Result<void> vkCheck(VkResult r, const char* what) {
  if (r == VK_SUCCESS) return {};
  return deviceError(std::string(what) + ": " + vkResultName(r), what, r);
}

}  // namespace rayspec
