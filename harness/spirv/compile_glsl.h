// GLSL -> SPIR-V with glslang as a library (Vulkan 1.2 client, SPIR-V 1.4),
// validated with SPIRV-Tools, cached by content hash (memory, and on disk when
// a cache folder is set).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "program/program.h"

namespace rayspec {

struct SpirvResult {
  std::vector<uint32_t> words;  // empty on error
  std::string error;            // glslang or SPIRV-Tools messages, with the GLSL line
  bool from_cache = false;
};

// `compute`: the text is raygen run as a compute shader (glsl/emit_compute.h).
SpirvResult compileGlsl(const std::string& glsl, Stage stage, bool compute = false);

// Folder for the on-disk cache (created when missing); empty disables it.
void setSpirvCacheDir(const std::string& dir);

}  // namespace rayspec
