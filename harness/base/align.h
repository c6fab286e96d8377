// Rounding a size or an offset up to a multiple of an alignment.
#pragma once

#include <cstdint>

namespace rayspec {

// The smallest multiple of `a` that is at least `v` (`v` itself when `a` is 0).
constexpr uint64_t alignUp(uint64_t v, uint64_t a) {
  return a ? (v + a - 1) / a * a : v;
}

}  // namespace rayspec
