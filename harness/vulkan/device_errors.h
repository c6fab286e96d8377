// What a failed Vulkan call means for the case, and the planted faults that
// make a call fail on purpose (tests of this handling).
//   VK_ERROR_DEVICE_LOST            Crash: the driver lost the device on this
//                                   case; the next case gets a new device.
//   VK_ERROR_OUT_OF_DEVICE_MEMORY,  NotSupported: the device cannot hold this
//   VK_ERROR_OUT_OF_HOST_MEMORY     case (never a pass).
//   any other error of             Refused (the case Fails): the driver refused
//   vkCreateRayTracingPipelinesKHR  a pipeline the validation layer accepted.
//   anything else                   Crash, naming the call and the VkResult.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "results/results.h"
#include "vulkan/vk_check.h"

namespace rayspec {

struct DeviceErrorStatus {
  SideStatus status = SideStatus::Crash;
  std::string detail;
  bool device_lost = false;  // the VkDevice must be made again before the next case
};

// What a Device error (vulkan/vk_check.h deviceError) means for the case.
DeviceErrorStatus classifyVulkanError(const Error& e);

// The planted faults of this kind: name -> the call that fails and how.
std::optional<InjectedVkError> deviceErrorFault(const std::string& name);
const std::vector<std::string>& deviceErrorFaultNames();

}  // namespace rayspec
