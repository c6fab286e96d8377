#include "run/vulkan_adapter.h"

namespace rayspec {

VulkanOptions vulkanOptions(const RunOptions& opt) {
  VulkanOptions v;
  v.device_filter = opt.device;
  v.validation = !opt.no_validation;
  if (opt.device_per_case == "yes") v.device_per_case = true;
  if (opt.device_per_case == "no") v.device_per_case = false;
  v.case_timeout_s = opt.timeout;
  return v;
}

VulkanAdapter::VulkanAdapter(const VulkanOptions& options) {
  if (Result<std::unique_ptr<VulkanEngine>> engine = VulkanEngine::create(options))
    backend_ = std::move(*engine);
  else
    error_ = engine.error().format();
}

std::string VulkanAdapter::description() const {
  if (!backend_) return "none (" + error_ + ")";
  return backend_->device().name + " (" + backend_->device().driver_info + ")";
}

Result<Results> VulkanAdapter::run(const Case& c, const Plan& plan) {
  if (backend_) return backend_->run(c, plan);
  Results r;
  r.backend = name();
  r.case_name = c.name;
  r.setStatus(SideStatus::NotSupported, error_);
  return r;
}

std::vector<std::string> VulkanAdapter::close() {
  return backend_ ? backend_->close() : std::vector<std::string>{};
}

}  // namespace rayspec
