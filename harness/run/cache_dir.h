// Where a run keeps what it may reuse across runs and worker processes: the
// SPIR-V of generated stages (<dir>/spirv, spirv/spirv_cache.h), each
// driver's VkPipelineCache (<dir>/pipelines, vulkan/pipeline_cache.h) and the
// cases' timings (<dir>/case-seconds.json, run/case_order.h). Without a
// folder on disk every worker compiles its stages again (on lavapipe with the
// validation layer that was 41% of an sbt/* run). --cache-dir '' turns it off.
#pragma once

#include <string>

#include "base/result.h"

namespace rayspec {

// $RAYSPEC_CACHE_DIR, else $XDG_CACHE_HOME/rayspec, else $HOME/.cache/rayspec;
// "" when none is set.
std::string defaultCacheDir();

// Points the SPIR-V cache at <dir>/spirv and the pipeline caches at
// <dir>/pipelines ("" : SPIR-V in memory only, no pipeline cache). The error
// when the SPIR-V cache's key cannot be had (spirv/cache_secret.h): its
// SPIR-V stays in memory then, and the pipeline caches are used.
Result<void> useCacheDir(const std::string& dir);

}  // namespace rayspec
