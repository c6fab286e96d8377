// Raygen run as a compute shader (Pipeline::from_compute, pipeline.traces:
// ray_query_compute, --through ray-query-compute, R-RQ-EQUIV): its traces are
// ray query loops (glsl/emit_ray_query.h) and what a ray tracing stage reads
// from the launch comes from the dispatch instead:
//   - the launch id from gl_GlobalInvocationID: invocations are numbered
//     x + y * (groups in x) * kComputeGroupSize, and invocation i is launch
//     id (i % width, i / width % height, i / (width * height)); those past
//     the launch's end return at once;
//   - the launch size is the case's, a constant;
//   - raygen's shader record data (pipeline.raygen_data) is a constant table.
#pragma once

#include <array>
#include <cstdint>

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

constexpr uint32_t kComputeGroupSize = 64;
// The most workgroups a dispatch may have in x (the least maximum Vulkan
// allows for maxComputeWorkGroupCount[0]).
constexpr uint32_t kComputeMaxGroupsX = 65535;

// The vkCmdDispatch group counts that cover `launch` (width, height, depth)
// in invocations numbered as above; all zero for an empty launch.
std::array<uint32_t, 3> computeGroups(const std::array<uint32_t, 3>& launch);

// Before the shared GLSL: the workgroup size and the RS_LAUNCH_ID /
// RS_LAUNCH_SIZE the shared GLSL and the built-ins read.
void emitComputeLaunch(const StageContext& raygen, GlslWriter& out);

// rs_shader_record_uint / _float over raygen's shader record data.
void emitComputeShaderRecord(const StageContext& raygen, GlslWriter& out);

// First in main(): this invocation's launch id, or return past the end.
void emitComputeLaunchId(const StageContext& raygen, GlslWriter& out);

}  // namespace rayspec
