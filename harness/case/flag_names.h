// Names of the Vulkan flag bits as written in cases (see case.h for values).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace rayspec {

using FlagTable = std::vector<std::pair<const char*, uint32_t>>;

const FlagTable& geometryFlagNames();  // opaque, no_duplicate_any_hit
const FlagTable& instanceFlagNames();  // triangle_facing_cull_disable, ...
const FlagTable& rayFlagNames();       // opaque, no_opaque, terminate_on_first_hit, ...
const FlagTable& pipelineFlagNames();  // skip_triangles, skip_aabbs, no_null_*, link-time
const FlagTable& buildFlagNames();     // prefer_fast_trace, prefer_fast_build, ...

// VkPipelineCreateFlagBits values of the pipeline flags.
constexpr uint32_t kPipelineSkipTriangles = 0x1000;
constexpr uint32_t kPipelineSkipAabbs = 0x2000;
// NO_NULL_*_SHADERS (R-NULL-SHADERS): the shader of that kind is present
// wherever it would run; reaching an all-zero record for one is undefined.
constexpr uint32_t kPipelineNoNullAnyHit = 0x4000;
constexpr uint32_t kPipelineNoNullClosestHit = 0x8000;
constexpr uint32_t kPipelineNoNullMiss = 0x10000;
constexpr uint32_t kPipelineNoNullIntersection = 0x20000;
constexpr uint32_t kPipelineNoNullShaders = kPipelineNoNullAnyHit | kPipelineNoNullClosestHit |
                                            kPipelineNoNullMiss | kPipelineNoNullIntersection;
// VK_EXT_graphics_pipeline_library's link-time bits, set on the pipeline
// and every library it links (as VK-GL-CTS's pipeline_library misc cases
// do): they may change how a driver compiles, never what a shader observes.
constexpr uint32_t kPipelineLinkTimeOptimization = 0x400;
constexpr uint32_t kPipelineRetainLinkTimeOptimizationInfo = 0x800000;
constexpr uint32_t kPipelineLinkTimeFlags =
    kPipelineLinkTimeOptimization | kPipelineRetainLinkTimeOptimizationInfo;

// VkBuildAccelerationStructureFlagBitsKHR values of scene.build.flags.
constexpr uint32_t kBuildAllowUpdate = 0x1;
constexpr uint32_t kBuildAllowCompaction = 0x2;
constexpr uint32_t kBuildPreferFastTrace = 0x4;
constexpr uint32_t kBuildPreferFastBuild = 0x8;
constexpr uint32_t kBuildLowMemory = 0x10;
// ALLOW_DATA_ACCESS (VK_KHR_ray_tracing_position_fetch): added wherever a
// stage reads vertex_position<i>.
constexpr uint32_t kBuildAllowDataAccess = 0x800;

}  // namespace rayspec
