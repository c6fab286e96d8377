// Writing a file whole or not at all: into a temporary name beside it (unique
// per process and thread), then renamed over it, so that a reader (another
// worker, another run) never sees half a file. Used by the caches that runs
// and workers share (SPIR-V, pipeline caches, case timings).
#pragma once

#include <cstddef>
#include <string>

namespace rayspec {

// False when it could not be written (nothing is left behind then).
bool writeFileWhole(const std::string& path, const void* data, size_t size);

}  // namespace rayspec
