#include "vulkan/vulkan_engine.h"

#include <algorithm>
#include <chrono>

#include "vulkan/context.h"
#include "vulkan/device_errors.h"
#include "vulkan/pipeline.h"
#include "vulkan/pipeline_cache.h"
#include "vulkan/run_case.h"
#include "vulkan/vk_check.h"

namespace rayspec {

VulkanEngine::VulkanEngine() : ctx_(std::make_unique<VulkanContext>()) {}

uint64_t waitTimeoutNs(double case_timeout_s) {
  const double ns = (case_timeout_s + 60.0) * 1e9;
  return std::max(kDefaultWaitTimeoutNs, static_cast<uint64_t>(std::min(ns, 1e18)));
}

VulkanEngine::~VulkanEngine() {
  close();
}

Result<std::unique_ptr<VulkanEngine>> VulkanEngine::create(const VulkanOptions& options) {
  std::unique_ptr<VulkanEngine> backend(new VulkanEngine());
  VulkanContext& ctx = *backend->ctx_;
  // On an error the destructor releases what exists (a device made before
  // the error included: has_device_ follows ctx.device).
  ctx.wait_timeout_ns = waitTimeoutNs(options.case_timeout_s);
  RAYSPEC_TRY_VOID(createInstance(ctx, options.validation));
  RAYSPEC_TRY_VOID(selectDevice(ctx, options.device_filter));
  const Result<void> device = createDevice(ctx);
  backend->has_device_ = ctx.device != VK_NULL_HANDLE;
  if (!device) return device.error();
  backend->device_per_case_ = options.device_per_case.value_or(devicePerCase(ctx.info.driver_name));
  if (!backend->device_per_case_) ctx.pipeline_cache = openPipelineCache(ctx);
  return backend;
}

const DeviceInfo& VulkanEngine::device() const {
  return ctx_->info;
}

bool VulkanEngine::validationEnabled() const {
  return ctx_->validation;
}

uint32_t VulkanEngine::validationLayerVersion() const {
  return ctx_->validation ? ctx_->validation_layer_version : 0;
}

Results VulkanEngine::run(const Case& c, const Plan& plan) {
  auto start = std::chrono::steady_clock::now();
  Results r;
  r.case_name = c.name;
  r.backend = "vulkan";
  r.device = ctx_->info.name;
  r.driver = ctx_->info.driver_info;
  r.width = c.rays.width;
  r.height = c.rays.height;
  ctx_->capture->take();  // messages from before this run are not its own
  try {
    if (const Result<void> ran = runOnDevice(c, plan, r); !ran) setErrorStatus(ran.error(), r);
  } catch (const std::exception& e) {
    // The standard library's own (std::bad_alloc, a vector's at()): the case
    // crashed the backend, and the run goes on.
    r.setStatus(SideStatus::Crash, e.what());
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

Result<void> VulkanEngine::runOnDevice(const Case& c, const Plan& plan, Results& r) {
  if (device_lost_) {  // the last case lost the device: this one gets a new one
    releaseDevice();
    has_device_ = false;
    device_lost_ = false;
  }
  if (!has_device_) {
    StepTimer setup_time(r.cost, CostStep::BackendSetup);
    const Result<void> made = createDevice(*ctx_);
    has_device_ = ctx_->device != VK_NULL_HANDLE;  // released after the case, even on an error
    if (!made) return made.error();
    if (!device_per_case_) ctx_->pipeline_cache = openPipelineCache(*ctx_);
  }
  return runCase(*ctx_, c, plan, r);
}

void VulkanEngine::setErrorStatus(const Error& e, Results& r) {
  switch (e.kind) {
    case ErrorKind::ShaderCompile:
      r.setStatus(SideStatus::InvalidShader,
                  "rayspec generated a stage that does not compile or validate: " + e.format());
      return;
    case ErrorKind::NotSupported:
      r.setStatus(SideStatus::NotSupported, e.format());
      return;
    case ErrorKind::Device: {
      const DeviceErrorStatus s = classifyVulkanError(e);
      r.setStatus(s.status, s.detail);
      device_lost_ = device_lost_ || s.device_lost;
      return;
    }
    case ErrorKind::Input:
    case ErrorKind::Harness:
      r.setStatus(SideStatus::Crash, e.format());
      return;
  }
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
