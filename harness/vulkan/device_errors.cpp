#include "vulkan/device_errors.h"

namespace rayspec {
namespace {

struct NamedFault {
  const char* name;
  InjectedVkError error;
};

const std::vector<NamedFault>& faults() {
  static const std::vector<NamedFault> table = {
      {"device-lost", {"vkWaitForFences", VK_ERROR_DEVICE_LOST}},
      {"out-of-device-memory", {"vkAllocateMemory", VK_ERROR_OUT_OF_DEVICE_MEMORY}},
      {"pipeline-refused", {"vkCreateRayTracingPipelinesKHR", VK_ERROR_INITIALIZATION_FAILED}},
  };
  return table;
}

}  // namespace

DeviceErrorStatus classifyVulkanError(const Error& e) {
  DeviceErrorStatus s;
  const std::string call = e.call.empty() ? std::string("a Vulkan call") : e.call;
  const std::string& result = e.result;
  if (result == vkResultName(VK_ERROR_DEVICE_LOST)) {
    s.status = SideStatus::Crash;
    s.device_lost = true;
    s.detail = "device lost: " + call + " returned " + result + "; the next case gets a new device";
  } else if (result == vkResultName(VK_ERROR_OUT_OF_DEVICE_MEMORY) ||
             result == vkResultName(VK_ERROR_OUT_OF_HOST_MEMORY)) {
    s.status = SideStatus::NotSupported;
    s.detail =
        "out of memory: " + call + " returned " + result + "; the device cannot hold this case";
  } else if (e.call == "vkCreateRayTracingPipelinesKHR") {
    s.status = SideStatus::Refused;
    s.detail = "the driver refused the pipeline: " + call + " returned " + result +
               " for a pipeline the validation layer accepted";
  } else {
    s.status = SideStatus::Crash;
    s.detail = e.format();
  }
  return s;
}

std::optional<InjectedVkError> deviceErrorFault(const std::string& name) {
  for (const NamedFault& f : faults())
    if (name == f.name) return f.error;
  return std::nullopt;
}

const std::vector<std::string>& deviceErrorFaultNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const NamedFault& f : faults()) n.push_back(f.name);
    return n;
  }();
  return names;
}

}  // namespace rayspec
