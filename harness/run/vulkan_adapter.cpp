#include "run/vulkan_adapter.h"

namespace rayspec {

VulkanAdapter::VulkanAdapter(const VulkanOptions& options) { backend_ = VulkanBackend::create(options, &error_); }

std::string VulkanAdapter::description() const {
  if (!backend_) return "none (" + error_ + ")";
  return backend_->device().name + " (" + backend_->device().driver_info + ")";
}

Results VulkanAdapter::run(const Case& c, const Plan& plan) {
  if (backend_) return backend_->run(c, plan);
  Results r;
  r.backend = name();
  r.case_name = c.name;
  r.setStatus(RunStatus::NotSupported, error_);
  return r;
}

std::vector<std::string> VulkanAdapter::close() { return backend_ ? backend_->close() : std::vector<std::string>{}; }

}  // namespace rayspec
