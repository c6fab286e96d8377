// A device for the tests of what a case needs of one (tests/run_library_support_test.cpp,
// tests/fuzz_generator_features_test.cpp): every feature, room for every
// library case's limits, every vertex format.
#pragma once

#include "case/vertex_format.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {

constexpr uint32_t kTestVulkan13 = (1u << 22) | (3u << 12);

inline DeviceInfo capableDevice() {
  DeviceInfo d;
  d.api_version_number = kTestVulkan13;
  d.max_ray_recursion_depth = 31;
  d.max_launch_size = {1u << 30, 1u << 30, 1u << 30};
  d.max_ray_dispatch_invocation_count = 1u << 30;
  d.shader_group_handle_size = 32;
  d.shader_group_handle_alignment = 32;
  d.shader_group_base_alignment = 64;
  d.max_shader_group_stride = 4096;
  d.ray_traversal_primitive_culling = d.pipeline_library = d.ray_query = d.opacity_micromap = true;
  d.ray_tracing_maintenance1 = d.trace_rays_indirect = d.trace_rays_indirect2 = true;
  d.position_fetch = d.scalar_block_layout = d.library_group_handles = d.invocation_reorder = true;
  d.graphics_pipeline_library = true;
  d.descriptor_indexing = true;
  d.acceleration_structure_host_commands = d.acceleration_structure_indirect_build = true;
  d.acceleration_structure_update_after_bind = d.sparse_binding = d.sparse_binding_queue = true;
  d.shader_int8 = d.shader_int16 = d.shader_int64 = d.shader_float16 = d.shader_float64 = true;
  for (const auto& row : enumNames<VertexFormat>()) d.vertex_formats.push_back(row.name);
  return d;
}

}  // namespace rayspec
