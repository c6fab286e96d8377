// The device side of one case in a child process (fork), so that a driver
// crash (a signal) becomes a Crash and a hang a Timeout while the run goes on.
// The child creates its own VkInstance / VkDevice (forking after Vulkan is
// initialised is unsafe), runs the case, destroys the device (validation
// errors at teardown join the case's validation messages), plants a fault
// when asked, writes the results bundle and exits; the parent reads the
// bundle back. The child writes no PNG / EXR (OpenEXR's thread pool belongs to
// the parent's threads and would wait forever in the child); the parent
// writes them after reading the bundle. Cost on lavapipe with the validation
// layer: about 0.2 s per case (instance + device creation).
#pragma once

#include <string>

#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"
#include "vulkan/vulkan_backend.h"

namespace rayspec {

struct DeviceRun {
  VulkanOptions vulkan;
  double timeout_seconds = 120.0;
  std::string fault;  // planted fault, or empty
};

// Results of the device with status "Crash: ..." / "Timeout: ..." when the
// child died or hung; the bundle is in dir. *fault_note says what the
// planted fault changed.
Results runDeviceIsolated(const Case& c, const Plan& plan, const Results& model, const DeviceRun& run,
                          const std::string& dir, std::string* fault_note);

// The same in this process with an existing backend (--no-isolation).
Results runDeviceInProcess(const Case& c, const Plan& plan, const Results& model, VulkanBackend* backend,
                           const std::string& backend_error, const std::string& fault, const std::string& dir,
                           std::string* fault_note);

}  // namespace rayspec
