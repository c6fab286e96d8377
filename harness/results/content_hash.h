// A stable 64-bit hash of bytes (FNV-1a): the same on every machine and
// build, so it can be written to disk and compared elsewhere. Keys the SPIR-V
// cache; a results bundle records the hash of its case's text (case_hash).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rayspec {

inline constexpr uint64_t kContentHashSeed = 0xcbf29ce484222325ull;

// Continues `h` over n bytes.
uint64_t contentHash(uint64_t h, const void* data, size_t n);
inline uint64_t contentHash(std::string_view text) {
  return contentHash(kContentHashSeed, text.data(), text.size());
}

// 16 lowercase hex digits.
std::string contentHashText(uint64_t h);
// contentHashText read back; nullopt for any other text ("-1", "0x1f", "12zz").
std::optional<uint64_t> contentHashFromText(const std::string& text);

}  // namespace rayspec
