// GLSL -> SPIR-V with glslang as a library (Vulkan 1.2 client, SPIR-V 1.4),
// validated with SPIRV-Tools, cached by content hash (memory, and on disk when
// a cache folder is set).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/result.h"
#include "program/program.h"

namespace rayspec {

struct SpirvResult {
  std::vector<uint32_t> words;  // empty on error
  std::string error;            // glslang or SPIRV-Tools messages, with the GLSL line
  bool from_cache = false;
};

// `compute`: the text is raygen run as a compute shader (glsl/emit_compute.h).
SpirvResult compileGlsl(const std::string& glsl, Stage stage, bool compute = false);

// The capabilities a module declares (the operand of each OpCapability), in order.
std::vector<uint32_t> declaredCapabilities(const std::vector<uint32_t>& words);

// Folder for the on-disk cache (created when missing); empty disables it.
// The error when the key of its sums (spirv/cache_secret.h) can be neither
// read nor made: the cache stays in memory only then.
Result<void> setSpirvCacheDir(const std::string& dir);

}  // namespace rayspec
