// Where a run keeps what it may reuse across runs and case processes: the
// SPIR-V of generated stages (<dir>/spirv, spirv/spirv_cache.h). Each case
// side runs in a fresh child process, so without a folder on disk every case
// compiles its stages again (on lavapipe with the validation layer that was
// 41% of an sbt/* run). --cache-dir '' turns it off.
#pragma once

#include <string>

namespace rayspec {

// $RAYSPEC_CACHE_DIR, else $XDG_CACHE_HOME/rayspec, else $HOME/.cache/rayspec;
// "" when none is set.
std::string defaultCacheDir();

// Points the SPIR-V cache at <dir>/spirv ("" leaves it in memory only).
void useCacheDir(const std::string& dir);

}  // namespace rayspec
