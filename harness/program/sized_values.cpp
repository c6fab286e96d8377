#include "program/sized_values.h"

#include <cfloat>
#include <cmath>

namespace rayspec {

bool exactInFloat16(double v) {
  if (v == 0) return true;
  const double a = std::fabs(v);
  if (!(a >= std::ldexp(1.0, -14) && a <= 65504.0)) return false;
  int exponent = 0;
  const double mantissa = std::frexp(a, &exponent);  // a = mantissa 2^exponent, [0.5, 1)
  const double scaled = std::ldexp(mantissa, 11);
  return scaled == std::floor(scaled);
}

bool exactInFloat32(double v) {
  if (v == 0) return true;
  const float f = static_cast<float>(v);
  return static_cast<double>(f) == v && std::fabs(f) >= FLT_MIN;
}

bool normalOrZero(double v) {
  return v == 0 || std::fpclassify(v) == FP_NORMAL;
}

uint64_t wrapToType(ValueType t, uint64_t bits) {
  const SizedType* s = sizedType(t);
  if (!s || s->bits >= 64) return bits;
  const uint64_t mask = (uint64_t{1} << s->bits) - 1;
  uint64_t low = bits & mask;
  const uint64_t sign = uint64_t{1} << (s->bits - 1);
  if (s->kind == SizedKind::Signed && (low & sign)) low |= ~mask;
  return low;
}

}  // namespace rayspec
