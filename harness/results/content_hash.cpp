#include "results/content_hash.h"

#include <charconv>
#include <cstdio>

namespace rayspec {

uint64_t contentHash(uint64_t h, const void* data, size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 0x100000001b3ull;
  }
  return h;
}

std::string contentHashText(uint64_t h) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

std::optional<uint64_t> contentHashFromText(const std::string& text) {
  uint64_t h = 0;
  const char* end = text.data() + text.size();
  if (text.size() != 16) return std::nullopt;
  for (const char c : text)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return std::nullopt;
  const std::from_chars_result read = std::from_chars(text.data(), end, h, 16);
  if (read.ec != std::errc() || read.ptr != end) return std::nullopt;
  return h;
}

}  // namespace rayspec
