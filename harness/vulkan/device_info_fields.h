// The one list of what rayspec knows of a physical device. Everything else is
// generated from it: the members of DeviceInfo (vulkan/vulkan_engine.h, each
// value-initialised: 0, false, empty), the JSON a driver probe's child sends
// its parent, both ways (run/device_info_json.h), and the limits `rayspec
// devices` prints under a usable device (cli/cmd_devices.cpp), in this order.
// What each member holds is read from the device in vulkan/device_select.cpp.
//
// X(type, member, "json key", "label", "meaning"):
//   type: a type with no comma in it (an alias where it has one: DeviceLaunchSize);
//   label: the name `rayspec devices` prints before the value, nullptr where
//     it prints none (the name, driver and Vulkan version are in the device's
//     heading line instead);
//   meaning: what the value is, in a line.
// The ray tracing properties are 0 without VK_KHR_ray_tracing_pipeline, and
// the features false on a device below Vulkan 1.2 (rayspec needs 1.2). From
// ray_traversal_primitive_culling to library_group_handles, what a case may
// need and the device may lack: such a case is NotSupported there
// (vulkan/case_support.h; `rayspec devices` counts the library's).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rayspec {

// Per launch dimension (x, y, z).
using DeviceLaunchSize = std::array<uint64_t, 3>;

}  // namespace rayspec

#define RAYSPEC_DEVICE_INFO_FIELDS(X)                                                              \
  X(uint32_t, index, "index", nullptr, "position in vkEnumeratePhysicalDevices")                   \
  X(std::string, name, "name", nullptr, "deviceName")                                              \
  X(std::string, driver_name, "driver_name", nullptr, "driverName (Vulkan 1.2; \"\" below)")       \
  X(std::string, driver_info, "driver_info", nullptr, "driverInfo (Vulkan 1.2; \"\" below)")       \
  X(std::string, api_version, "api_version", nullptr, "apiVersion as major.minor.patch")           \
  X(uint32_t, api_version_number, "api_version_number", nullptr,                                   \
    "VkPhysicalDeviceProperties::apiVersion")                                                      \
  X(std::string, device_uuid, "device_uuid", nullptr,                                              \
    "deviceUUID-driverUUID in hex (Vulkan 1.1; \"\" below)")                                       \
  X(std::string, pipeline_cache_uuid, "pipeline_cache_uuid", nullptr, "pipelineCacheUUID in hex")  \
  X(std::string, conformance_version, "conformance_version", nullptr,                              \
    "conformanceVersion as major.minor.subminor.patch (Vulkan 1.2; \"\" below; 0.0.0.0: none)")    \
  X(std::string, driver_id, "driver_id", nullptr,                                                  \
    "driverID: the VkDriverId's name as vulkan.hpp spells it (Vulkan 1.2; \"\" below)")            \
  X(bool, ray_tracing_extension, "ray_tracing_extension", nullptr,                                 \
    "VK_KHR_ray_tracing_pipeline is offered")                                                      \
  X(bool, acceleration_structure_extension, "acceleration_structure_extension", nullptr,           \
    "VK_KHR_acceleration_structure and VK_KHR_deferred_host_operations are offered")               \
  X(bool, cpu, "cpu", nullptr,                                                                     \
    "VK_PHYSICAL_DEVICE_TYPE_CPU (lavapipe): the device's work is this machine's cores")           \
  X(bool, ray_tracing_pipeline, "ray_tracing_pipeline", nullptr,                                   \
    "the rayTracingPipeline feature on a Vulkan 1.2 device")                                       \
  X(bool, acceleration_structure, "acceleration_structure", nullptr,                               \
    "the accelerationStructure feature on a Vulkan 1.2 device")                                    \
  X(uint32_t, shader_group_handle_size, "shader_group_handle_size", "shaderGroupHandleSize",       \
    "ray tracing pipeline property")                                                               \
  X(uint32_t, shader_group_handle_alignment, "shader_group_handle_alignment",                      \
    "shaderGroupHandleAlignment", "ray tracing pipeline property")                                 \
  X(uint32_t, shader_group_base_alignment, "shader_group_base_alignment",                          \
    "shaderGroupBaseAlignment", "ray tracing pipeline property")                                   \
  X(uint32_t, max_ray_recursion_depth, "max_ray_recursion_depth", "maxRayRecursionDepth",          \
    "ray tracing pipeline property")                                                               \
  X(uint32_t, max_ray_hit_attribute_size, "max_ray_hit_attribute_size", "maxRayHitAttributeSize",  \
    "ray tracing pipeline property")                                                               \
  X(uint32_t, max_shader_group_stride, "max_shader_group_stride", "maxShaderGroupStride",          \
    "ray tracing pipeline property")                                                               \
  X(uint32_t, max_ray_dispatch_invocation_count, "max_ray_dispatch_invocation_count",              \
    "maxRayDispatchInvocationCount", "ray tracing pipeline property")                              \
  X(uint32_t, shader_group_handle_capture_replay_size, "shader_group_handle_capture_replay_size",  \
    "shaderGroupHandleCaptureReplaySize", "ray tracing pipeline property")                         \
  X(uint64_t, max_geometry_count, "max_geometry_count", "maxGeometryCount",                        \
    "acceleration structure property")                                                             \
  X(uint64_t, max_instance_count, "max_instance_count", "maxInstanceCount",                        \
    "acceleration structure property")                                                             \
  X(uint64_t, max_primitive_count, "max_primitive_count", "maxPrimitiveCount",                     \
    "acceleration structure property")                                                             \
  X(uint32_t, max_per_stage_descriptor_acceleration_structures,                                    \
    "max_per_stage_descriptor_acceleration_structures",                                            \
    "maxPerStageDescriptorAccelerationStructures", "acceleration structure property")              \
  X(uint32_t, max_per_stage_descriptor_update_after_bind_acceleration_structures,                  \
    "max_per_stage_descriptor_update_after_bind_acceleration_structures",                          \
    "maxPerStageDescriptorUpdateAfterBindAccelerationStructures",                                  \
    "acceleration structure property")                                                             \
  X(uint32_t, max_descriptor_set_acceleration_structures,                                          \
    "max_descriptor_set_acceleration_structures", "maxDescriptorSetAccelerationStructures",        \
    "acceleration structure property")                                                             \
  X(uint32_t, max_descriptor_set_update_after_bind_acceleration_structures,                        \
    "max_descriptor_set_update_after_bind_acceleration_structures",                                \
    "maxDescriptorSetUpdateAfterBindAccelerationStructures", "acceleration structure property")    \
  X(uint32_t, min_acceleration_structure_scratch_offset_alignment,                                 \
    "min_acceleration_structure_scratch_offset_alignment",                                         \
    "minAccelerationStructureScratchOffsetAlignment", "acceleration structure property")           \
  X(bool, acceleration_structure_update_after_bind, "acceleration_structure_update_after_bind",    \
    "descriptorBindingAccelerationStructureUpdateAfterBind", "acceleration structure feature")     \
  X(uint32_t, max_image_dimension_2d, "max_image_dimension_2d", nullptr,                           \
    "maxImageDimension2D: the widest and tallest image a case may write")                          \
  X(uint32_t, max_storage_buffer_range, "max_storage_buffer_range", nullptr,                       \
    "maxStorageBufferRange: the largest buffer a case may bind")                                   \
  X(DeviceLaunchSize, max_launch_size, "max_launch_size", nullptr,                                 \
    "maxComputeWorkGroupCount * maxComputeWorkGroupSize: the largest vkCmdTraceRaysKHR launch")    \
  X(bool, acceleration_structure_host_commands, "acceleration_structure_host_commands",            \
    "accelerationStructureHostCommands", "the acceleration structure feature")                     \
  X(bool, acceleration_structure_indirect_build, "acceleration_structure_indirect_build",          \
    "accelerationStructureIndirectBuild", "the acceleration structure feature")                    \
  X(bool, sparse_binding, "sparse_binding", "sparseBinding",                                       \
    "the device feature (scene.build.sparse, --through sparse)")                                   \
  X(bool, sparse_binding_queue, "sparse_binding_queue", "sparse binding queue",                    \
    "the queue family rayspec runs on (the first with compute) has VK_QUEUE_SPARSE_BINDING_BIT")   \
  X(bool, ray_traversal_primitive_culling, "ray_traversal_primitive_culling",                      \
    "rayTraversalPrimitiveCulling",                                                                \
    "the ray tracing pipeline feature (skip_triangles, skip_aabbs)")                               \
  X(bool, pipeline_library, "pipeline_library", "VK_KHR_pipeline_library",                         \
    "VK_KHR_pipeline_library is offered")                                                          \
  X(bool, graphics_pipeline_library, "graphics_pipeline_library",                                  \
    "VK_EXT_graphics_pipeline_library",                                                            \
    "offered with VK_KHR_pipeline_library (pipeline.flags link_time_optimization, "                \
    "retain_link_time_optimization_info)")                                                         \
  X(bool, ray_query, "ray_query", "VK_KHR_ray_query",                                              \
    "VK_KHR_ray_query and its rayQuery feature (--through ray-query)")                             \
  X(bool, opacity_micromap, "opacity_micromap", "VK_EXT_opacity_micromap",                         \
    "VK_EXT_opacity_micromap is offered (rayspec enables it on Vulkan 1.3 only)")                  \
  X(bool, ray_tracing_maintenance1, "ray_tracing_maintenance1", "VK_KHR_ray_tracing_maintenance1", \
    "the extension with its rayTracingMaintenance1 feature (gl_CullMaskEXT, cull_mask)")           \
  X(bool, trace_rays_indirect, "trace_rays_indirect", "vkCmdTraceRaysIndirectKHR",                 \
    "rayTracingPipelineTraceRaysIndirect")                                                         \
  X(bool, trace_rays_indirect2, "trace_rays_indirect2", "vkCmdTraceRaysIndirect2KHR",              \
    "maintenance1's rayTracingPipelineTraceRaysIndirect2")                                         \
  X(bool, position_fetch, "position_fetch", "VK_KHR_ray_tracing_position_fetch",                   \
    "the extension with its rayTracingPositionFetch feature (the vertex_position<i> built-ins)")   \
  X(bool, invocation_reorder, "invocation_reorder", "VK_NV_ray_tracing_invocation_reorder",        \
    "the extension with its rayTracingInvocationReorder feature (hit objects: hit_object.*, "      \
    "execute, record_miss, record_empty, reorder)")                                                \
  X(bool, scalar_block_layout, "scalar_block_layout", "scalarBlockLayout",                         \
    "Vulkan 1.2's feature (a scalar shader record block, pipeline.sbt.record_layout)")             \
  X(bool, descriptor_indexing, "descriptor_indexing", "descriptorIndexing",                        \
    "Vulkan 1.2's feature (VK_EXT_descriptor_indexing: top levels indexed dynamically, tlas: "     \
    "expr)")                                                                                       \
  X(bool, shader_int8, "shader_int8", "shaderInt8",                                                \
    "Vulkan 1.2's feature (VK_KHR_shader_float16_int8: int8, uint8 locals)")                       \
  X(bool, shader_int16, "shader_int16", "shaderInt16", "the core feature (int16, uint16 locals)")  \
  X(bool, shader_int64, "shader_int64", "shaderInt64", "the core feature (int64, uint64 locals)")  \
  X(bool, shader_float16, "shader_float16", "shaderFloat16",                                       \
    "Vulkan 1.2's feature (VK_KHR_shader_float16_int8: float16 locals)")                           \
  X(bool, shader_float64, "shader_float64", "shaderFloat64", "the core feature (float64 locals)")  \
  X(bool, library_group_handles, "library_group_handles", "VK_EXT_pipeline_library_group_handles", \
    "the extension with its pipelineLibraryGroupHandles feature (a library's group handles "       \
    "are the linked pipeline's)")                                                                  \
  X(std::vector<std::string>, vertex_formats, "vertex_formats", "vertex formats (AS build)",       \
    "formats of ACCELERATION_STRUCTURE_VERTEX_BUFFER: rayspec's names (float3, half2, ...) "       \
    "for those a case may name, the VkFormat's name otherwise")
