// Shader binding table test helpers shared by the vulkan module's tests.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "vulkan/sbt_layout.h"

namespace rayspec::sbt_test {

// Handle bytes of group g: every byte 0x10 + g, so a copied handle is visible.
inline std::vector<uint8_t> fakeHandles(const Pipeline& p, const SbtLimits& l) {
  std::vector<uint8_t> h(sbtGroupCount(p) * l.handle_size);
  for (size_t i = 0; i < h.size(); ++i) h[i] = static_cast<uint8_t>(0x10 + i / l.handle_size);
  return h;
}

inline bool allBytes(const std::vector<uint8_t>& b, uint64_t at, uint64_t n, uint8_t v) {
  for (uint64_t i = 0; i < n; ++i)
    if (b[at + i] != v) return false;
  return true;
}

inline uint32_t wordAt(const std::vector<uint8_t>& b, uint64_t at) {
  uint32_t w;
  std::memcpy(&w, b.data() + at, 4);
  return w;
}

}  // namespace rayspec::sbt_test
