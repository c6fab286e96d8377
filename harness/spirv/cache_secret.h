// The secret that keys the SPIR-V cache's sums (spirv/spirv_cache.h): a sum
// is HMAC-SHA-256 under it, so a cache folder others can write (a shared
// RAYSPEC_CACHE_DIR, a CI cache restored from another job) cannot pass a
// module off as the one compiled from a text: without the secret no sum can be
// made. It lives outside every cache folder, in the user's configuration:
// <config>/spirv-cache.key, <config> being $RAYSPEC_CONFIG_DIR, else
// $XDG_CONFIG_HOME/rayspec, else $HOME/.config/rayspec. kCacheSecretBytes
// random bytes, made mode 0600 on first use (the folder 0700 when it is made).
// The file is read as untrusted input: one that is a link or not a regular
// file, not the user's, open to group or others, or not kCacheSecretBytes long
// is replaced by a new secret (every entry keyed with the old one is then a
// miss, compiled again).
#pragma once

#include <cstddef>
#include <string>

#include "base/result.h"

namespace rayspec {

constexpr size_t kCacheSecretBytes = 32;

// <config>/spirv-cache.key; "" when none of the three variables is set.
std::string cacheSecretFile();

// The secret in `file`, made (or replaced) there when missing or unusable;
// the error naming the file when it can be neither read nor made.
Result<std::string> loadCacheSecret(const std::string& file);

}  // namespace rayspec
