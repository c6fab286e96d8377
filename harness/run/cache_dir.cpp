#include "run/cache_dir.h"

#include <cstdlib>

#include "spirv/compile_glsl.h"
#include "vulkan/pipeline_cache.h"

namespace rayspec {

std::string defaultCacheDir() {
  if (const char* d = std::getenv("RAYSPEC_CACHE_DIR")) return d;
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return std::string(d) + "/rayspec";
  if (const char* d = std::getenv("HOME"); d && *d) return std::string(d) + "/.cache/rayspec";
  return {};
}

Result<void> useCacheDir(const std::string& dir) {
  setPipelineCacheDir(dir.empty() ? std::string() : dir + "/pipelines");
  return setSpirvCacheDir(dir.empty() ? std::string() : dir + "/spirv");
}

}  // namespace rayspec
