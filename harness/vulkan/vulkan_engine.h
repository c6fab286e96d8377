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

namespace rayspec {

struct VulkanOptions {
  std::string device_filter;            // substring of the device name (case-insensitive);
                                        // empty = first device with VK_KHR_ray_tracing_pipeline
  bool validation = true;               // enable VK_LAYER_KHRONOS_validation when installed
  std::optional<bool> device_per_case;  // a VkDevice per case; unset: devicePerCase(driver name)
};

// Whether each case gets a VkDevice of its own (the instance lives on). Yes
// on lavapipe: it numbers shader group handles per device and bakes the
// numbers into the pipeline's one compute shader, so on a device that has
// made pipelines before, every pipeline is new to Mesa's shader cache and is
// compiled again (about 0.35 s a case, measured on Mesa 25.0.7); a new device
// starts the numbering afresh. Elsewhere one device serves every case.
bool devicePerCase(const std::string& driver_name);

struct DeviceInfo {
  uint32_t index = 0;  // position in vkEnumeratePhysicalDevices
  std::string name, driver_name, driver_info, api_version;
  uint32_t api_version_number = 0;  // VkPhysicalDeviceProperties::apiVersion
  std::string device_uuid;          // deviceUUID-driverUUID in hex (Vulkan 1.1; "" below)
  // The extensions (VK_KHR_acceleration_structure with
  // VK_KHR_deferred_host_operations) ...
  bool ray_tracing_extension = false, acceleration_structure_extension = false;
  bool cpu =
      false;  // VK_PHYSICAL_DEVICE_TYPE_CPU (lavapipe): the device's work is this machine's cores
  // ... and the features on a Vulkan 1.2 device (what rayspec needs).
  bool ray_tracing_pipeline = false, acceleration_structure = false;
  uint32_t shader_group_handle_size = 0, shader_group_handle_alignment = 0,
           shader_group_base_alignment = 0, max_ray_recursion_depth = 0,
           max_ray_hit_attribute_size = 0, max_shader_group_stride = 0,
           max_ray_dispatch_invocation_count = 0;
  // Launch and binding limits a case's size meets (vkCmdTraceRaysKHR: each
  // launch dimension at most maxComputeWorkGroupCount * maxComputeWorkGroupSize).
  uint32_t max_image_dimension_2d = 0, max_storage_buffer_range = 0;
  uint64_t max_launch_size[3] = {0, 0, 0};
  bool acceleration_structure_host_commands = false;
  // Optional features a case may need (NotSupported without them).
  bool pipeline_library = false;  // VK_KHR_pipeline_library
  bool opacity_micromap = false;  // VK_EXT_opacity_micromap (on a Vulkan 1.3 device)
  // VK_KHR_ray_tracing_maintenance1 with its rayTracingMaintenance1 feature
  // (gl_CullMaskEXT, the cull_mask built-in).
  bool ray_tracing_maintenance1 = false;
  // vkCmdTraceRaysIndirectKHR (rayTracingPipelineTraceRaysIndirect) and
  // vkCmdTraceRaysIndirect2KHR (maintenance1's rayTracingPipelineTraceRaysIndirect2).
  bool trace_rays_indirect = false, trace_rays_indirect2 = false;
  // VK_KHR_ray_tracing_position_fetch with its rayTracingPositionFetch
  // feature (gl_HitTriangleVertexPositionsEXT, the vertex_position<i> built-ins).
  bool position_fetch = false;
  // Vulkan 1.2's scalarBlockLayout (a scalar shader record block,
  // pipeline.sbt.record_layout).
  bool scalar_block_layout = false;
  // VK_EXT_pipeline_library_group_handles with its pipelineLibraryGroupHandles
  // feature (library group handles identical to the linked pipeline's).
  bool library_group_handles = false;
  // The vertex formats the device builds triangles from
  // (ACCELERATION_STRUCTURE_VERTEX_BUFFER): rayspec's names (float3, half2,
  // ...) for the formats a case may name, the VkFormat's name otherwise.
  std::vector<std::string> vertex_formats;
};

// Every physical device the loader sees (with or without ray tracing).
Result<std::vector<DeviceInfo>> listDevices();

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
  // The driver library the device's commands live in (its path, as loaded),
  // found with dladdr on a device command; "" when unknown. With the
  // validation layer on, asks a second, layer-free instance (driver_library.cpp).
  std::string driverLibrary() const;

  // Never throws. status: Ok, NotSupported or Crash, with the detail. With a
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
  std::unique_ptr<VulkanContext> ctx_;
  bool device_lost_ = false;      // a case lost the device: the next run makes a new one
  bool device_per_case_ = false;  // devicePerCase(): made before and destroyed after each case
  bool has_device_ = false;
};

}  // namespace rayspec
