#include "vulkan/vulkan_engine.h"

#include <chrono>

#include "vulkan/context.h"
#include "vulkan/device_errors.h"
#include "vulkan/pipeline.h"
#include "vulkan/pipeline_cache.h"
#include "vulkan/run_case.h"
#include "vulkan/vk_check.h"

namespace rayspec {

VulkanEngine::VulkanEngine() : ctx_(std::make_unique<VulkanContext>()) {}

VulkanEngine::~VulkanEngine() {
  close();
}

Result<std::unique_ptr<VulkanEngine>> VulkanEngine::create(const VulkanOptions& options) {
  std::unique_ptr<VulkanEngine> backend(new VulkanEngine());
  VulkanContext& ctx = *backend->ctx_;
  try {
    createInstance(ctx, options.validation);
    if (Result<void> selected = selectDevice(ctx, options.device_filter); !selected)
      return selected.error();
    createDevice(ctx);
    backend->has_device_ = true;
    backend->device_per_case_ =
        options.device_per_case.value_or(devicePerCase(ctx.info.driver_name));
    if (!backend->device_per_case_) ctx.pipeline_cache = openPipelineCache(ctx);
  } catch (const std::exception& e) {
    return errorMessage(e.what());  // the destructor releases what exists
  }
  return backend;
}

const DeviceInfo& VulkanEngine::device() const {
  return ctx_->info;
}

bool VulkanEngine::validationEnabled() const {
  return ctx_->validation;
}

Results VulkanEngine::run(const Case& c, const Plan& plan) {
  auto start = std::chrono::steady_clock::now();
  Results r;
  r.case_name = c.name;
  r.backend = "vulkan";
  r.device = ctx_->info.name;
  r.width = c.rays.width;
  r.height = c.rays.height;
  ctx_->capture->take();  // messages from before this run are not its own
  try {
    if (device_lost_) {  // the last case lost the device: this one gets a new one
      releaseDevice();
      has_device_ = false;
      device_lost_ = false;
    }
    if (!has_device_) {
      StepTimer setup_time(r.cost, CostStep::BackendSetup);
      createDevice(*ctx_);
      has_device_ = true;
      if (!device_per_case_) ctx_->pipeline_cache = openPipelineCache(*ctx_);
    }
    runCase(*ctx_, c, plan, r);
  } catch (const ShaderCompileError& e) {
    r.setStatus(
        SideStatus::InvalidShader,
        std::string("rayspec generated a stage that does not compile or validate: ") + e.what());
  } catch (const NotSupportedError& e) {
    r.setStatus(SideStatus::NotSupported, e.what());
  } catch (const VulkanError& e) {
    const DeviceErrorStatus s = classifyVulkanError(e);
    r.setStatus(s.status, s.detail);
    device_lost_ = device_lost_ || s.device_lost;
  } catch (const std::exception& e) {
    r.setStatus(SideStatus::Crash, e.what());
  } catch (...) {
    r.setStatus(SideStatus::Crash, "unknown exception");
  }
  if (device_per_case_ && has_device_) {
    StepTimer teardown_time(r.cost, CostStep::BackendTeardown);
    releaseDevice();
  }
  if (!r.ok()) {
    r.records.clear();
    r.counters.clear();
    r.images.clear();
  }
  r.validation_messages = ctx_->capture->take();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

void VulkanEngine::releaseDevice() {
  if (ctx_->device) closePipelineCache(*ctx_, ctx_->pipeline_cache);
  ctx_->pipeline_cache = VK_NULL_HANDLE;
  destroyDevice(*ctx_);
  has_device_ = false;
}

bool devicePerCase(const std::string& driver_name) {
  return driver_name == "llvmpipe";
}

std::vector<std::string> VulkanEngine::close() {
  if (!ctx_) return {};
  ctx_->capture->take();
  if (has_device_) releaseDevice();
  destroyInstance(*ctx_);
  return ctx_->capture->take();
}

}  // namespace rayspec
