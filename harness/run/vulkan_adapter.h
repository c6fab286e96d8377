// The Vulkan device as a Backend.
#pragma once

#include <memory>

#include "run/backend.h"
#include "run/run_options.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {

// The device options a run asks for (--device, validation, --device-per-case).
VulkanOptions vulkanOptions(const RunOptions& opt);

class VulkanAdapter : public Backend {
 public:
  // Creates the instance and device now. Without a device, run() answers
  // NotSupported with the reason (error()).
  explicit VulkanAdapter(const VulkanOptions& options);
  std::string name() const override { return "vulkan"; }
  std::string description() const override;
  Result<Results> run(const Case& c, const Plan& plan) override;
  std::vector<std::string> close() override;

  bool found() const { return backend_ != nullptr; }
  const std::string& error() const { return error_; }
  bool validationEnabled() const { return backend_ && backend_->validationEnabled(); }
  uint32_t validationLayerVersion() const {
    return backend_ ? backend_->validationLayerVersion() : 0;
  }
  // What the device offers (found() only).
  const DeviceInfo& deviceInfo() const { return backend_->device(); }
  std::string driverLibrary() const { return backend_ ? backend_->driverLibrary() : std::string(); }
  bool cpuDevice() const { return backend_ && backend_->device().cpu; }
  std::string deviceUuid() const {
    return backend_ ? backend_->device().device_uuid : std::string();
  }

 private:
  std::unique_ptr<VulkanEngine> backend_;
  std::string error_;
};

}  // namespace rayspec
