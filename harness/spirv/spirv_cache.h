// The SPIR-V cache: content hash -> words, in memory and, when setSpirvCacheDir
// named a folder, on disk as <dir>/<16 hex digits>.spv. Thread-safe.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "program/program.h"

namespace rayspec {

// FNV-1a 64 of a version tag, the stage and the GLSL text.
uint64_t spirvCacheKey(const std::string& glsl, Stage stage);
std::string spirvCacheFileName(uint64_t key);  // "0123456789abcdef.spv"

bool spirvCacheLookup(uint64_t key, std::vector<uint32_t>& words);
void spirvCacheStore(uint64_t key, const std::vector<uint32_t>& words);

// Drops the in-memory entries (the disk cache stays); for tests.
void clearSpirvMemoryCache();

}  // namespace rayspec
