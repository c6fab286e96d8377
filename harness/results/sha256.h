// SHA-256 (OpenSSL's libcrypto), as 64 lower-case hex digits: the hash of
// anything a collision of would turn into a verdict, such as the SPIR-V
// cache's keys; and HMAC-SHA-256, a sum only the holder of a secret can make,
// such as the check of each SPIR-V cache entry (spirv/spirv_cache.h).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "base/result.h"

namespace rayspec {

// The digest of the pieces, one after the other; the error when libcrypto
// fails (it cannot allocate).
Result<std::string> sha256Hex(std::initializer_list<std::string_view> pieces);

// HMAC-SHA-256 of the pieces, one after the other, under `key`; the error
// when libcrypto fails.
Result<std::string> hmacSha256Hex(std::string_view key,
                                  std::initializer_list<std::string_view> pieces);

}  // namespace rayspec
