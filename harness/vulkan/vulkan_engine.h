// The Vulkan backend: runs one case on a Vulkan ray tracing device and returns
// its Results. One VkInstance / VkDevice lives as long as the backend and is
// reused across cases; everything else (acceleration structures, pipeline,
// descriptors, SBT, buffers, images) is created and destroyed inside run().
//
// Device features enabled (see device.cpp): rayTracingPipeline,
// accelerationStructure, bufferDeviceAddress (all required), and when the
// device has them: rayTraversalPrimitiveCulling, scalarBlockLayout,
// vulkanMemoryModel (+ device scope), shaderInt64.
// Device extensions: VK_KHR_ray_tracing_pipeline, VK_KHR_acceleration_structure,
// VK_KHR_deferred_host_operations.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/result.h"
#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"
#include "vulkan/device_info_fields.h"

namespace rayspec {

struct VulkanOptions {
  std::string device_filter;            // substring of the device name (case-insensitive);
                                        // empty = first device with VK_KHR_ray_tracing_pipeline
  bool validation = true;               // enable VK_LAYER_KHRONOS_validation when installed
  std::optional<bool> device_per_case;  // a VkDevice per case; unset: devicePerCase(driver name)
  double case_timeout_s = 0;            // the case's device timeout (0: none); a submission
                                        // waits past it (VulkanContext::wait_timeout_ns)
};

// Whether each case gets a VkDevice of its own (the instance lives on). Yes
// on lavapipe: it numbers shader group handles per device and bakes the
// numbers into the pipeline's one compute shader, so on a device that has
// made pipelines before, every pipeline is new to Mesa's shader cache and is
// compiled again (about 0.35 s a case, measured on Mesa 25.0.7); a new device
// starts the numbering afresh. Elsewhere one device serves every case.
bool devicePerCase(const std::string& driver_name);

// A submission's fence wait: a minute past the case's device timeout, at
// least 240 s (a hang guard where no timeout is set: --in-process).
uint64_t waitTimeoutNs(double case_timeout_s);

// What rayspec knows of a physical device: a member per row of
// vulkan/device_info_fields.h, which says what each holds.
struct DeviceInfo {
#define RAYSPEC_DEVICE_INFO_MEMBER(type, member, ...) type member{};
  RAYSPEC_DEVICE_INFO_FIELDS(RAYSPEC_DEVICE_INFO_MEMBER)
#undef RAYSPEC_DEVICE_INFO_MEMBER
};

// Every physical device the loader sees (with or without ray tracing).
Result<std::vector<DeviceInfo>> listDevices();

// The Khronos validation layer installed (VK_LAYER_KHRONOS_validation): its
// specVersion, the Vulkan header it was built with; 0 when none is.
uint32_t installedValidationLayer();
// The validation layer an engine made with VulkanOptions::validation `want`
// runs under: the installed layer's specVersion where it is wanted and the
// debug messenger it reports through is there; 0 when none is on.
uint32_t validationLayerFor(bool want);
// A Vulkan version as major.minor.patch.
std::string vulkanVersionText(uint32_t version);

struct VulkanContext;  // internal (vulkan/context.h)

// The Vulkan engine: one VkInstance and device that run cases. It is not a
// Backend (run/backend.h); VulkanAdapter (run/) adapts it to one.
class VulkanEngine {
 public:
  // The engine, or the error when no instance, no matching ray tracing device,
  // or device creation failed.
  static Result<std::unique_ptr<VulkanEngine>> create(const VulkanOptions& options);
  ~VulkanEngine();

  const DeviceInfo& device() const;
  bool validationEnabled() const;
  // The layer's specVersion while it is on (validationLayerFor), 0 while off.
  uint32_t validationLayerVersion() const;
  // The driver library the device's commands live in (its path, as loaded),
  // found with dladdr on a device command; "" when unknown. With the
  // validation layer on, asks a second, layer-free instance (driver_library.cpp).
  std::string driverLibrary() const;

  // status: Ok, or what went wrong (setErrorStatus), with the detail. With a
  // device per case, what the layer reports as the device is destroyed is the
  // case's own.
  Results run(const Case& c, const Plan& plan);

  // Destroys the device and the instance now (the destructor does it too) and
  // returns the validation errors reported while doing so (e.g. leaked
  // objects, which the layer reports at vkDestroyDevice).
  std::vector<std::string> close();

 private:
  VulkanEngine();
  void releaseDevice();  // saves the pipeline cache, destroys the device
  // The case on the device (made anew first when there is none, or it was lost).
  Result<void> runOnDevice(const Case& c, const Plan& plan, Results& r);
  // The status an error of the case gives: ShaderCompile InvalidShader,
  // NotSupported NotSupported, Device what classifyVulkanError says (and a
  // lost device is made anew for the next case), any other Crash.
  void setErrorStatus(const Error& e, Results& r);
  std::unique_ptr<VulkanContext> ctx_;
  bool device_lost_ = false;      // a case lost the device: the next run makes a new one
  bool device_per_case_ = false;  // devicePerCase(): made before and destroyed after each case
  bool has_device_ = false;
};

}  // namespace rayspec
