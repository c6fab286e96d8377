// Float arithmetic named once: the unit roundoff that every error bound of
// the model is written in, and stepping to a neighbouring float.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rayspec {

// u = 2^-24: the relative error of one rounding to float (round to nearest).
// Error bounds are written as a count of roundings times u.
constexpr double kUnitRoundoff = 0x1p-24;

// The next float above / below x; NaN stays NaN, and the infinity in the
// direction of the step stays itself. Inline: the model's fast path steps
// both ends of every launch ray.
inline float nextUp(float x) {
  if (std::isnan(x) || x == std::numeric_limits<float>::infinity()) return x;
  if (x == 0.0f) return std::numeric_limits<float>::denorm_min();
  const uint32_t bits = std::bit_cast<uint32_t>(x);
  return std::bit_cast<float>(x > 0 ? bits + 1 : bits - 1);
}
inline float nextDown(float x) {
  return -nextUp(-x);
}

// The nearest float at or below / at or above the double x (NaN stays NaN):
// a double bound rounded outward.
float floatBelow(double x);
float floatAbove(double x);

}  // namespace rayspec
