// The SPIR-V cache: key -> words, in memory and, when setSpirvCacheDir named
// a folder, on disk as <dir>/<key>.spv (the module as it is, for spirv-val
// and the device pack) beside <dir>/<key>.sum (HMAC-SHA-256 of the key and
// the module under the user's secret, spirv/cache_secret.h: whoever can
// write the folder but lacks the secret cannot make a sum that matches). An
// entry on disk is used only when both are regular files, the module is
// within kMaxCachedModuleBytes and SPIR-V, and the sum matches it and its
// key; anything else (a sum made without the secret, such as a plain
// SHA-256) is a miss, and the entry is written anew (a link or FIFO in its
// place removed first). Thread-safe.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "program/program.h"

namespace rayspec {

constexpr uint64_t kMaxCachedModuleBytes = 16ull << 20;

// SHA-256 of a version tag, the stage and the GLSL text (64 hex digits): a
// module found under it was compiled from that text. "" when libcrypto
// cannot make one: the cache is not used then (compileGlsl).
// `compute` (raygen run as a compute shader) is part of the stage.
std::string spirvCacheKey(const std::string& glsl, Stage stage, bool compute = false);
std::string spirvCacheFileName(const std::string& key);  // "<key>.spv"
std::string spirvCacheSumName(const std::string& key);   // "<key>.sum"

bool spirvCacheLookup(const std::string& key, std::vector<uint32_t>& words);
void spirvCacheStore(const std::string& key, const std::vector<uint32_t>& words);

// Drops the in-memory entries (the disk cache stays); for tests.
void clearSpirvMemoryCache();

}  // namespace rayspec
