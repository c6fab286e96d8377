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
const FlagTable& pipelineFlagNames();  // skip_triangles, skip_aabbs

// VkPipelineCreateFlagBits values of the pipeline flags.
constexpr uint32_t kPipelineSkipTriangles = 0x1000;
constexpr uint32_t kPipelineSkipAabbs = 0x2000;

}  // namespace rayspec
