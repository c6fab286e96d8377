#include "base/affine.h"

namespace rayspec {
namespace {

template <class M, class V, class W>
V apply(const M& m, const V& v, W w) {
  V r;
  for (int row = 0; row < 3; ++row)
    r[row] = m[row * 4] * v[0] + m[row * 4 + 1] * v[1] + m[row * 4 + 2] * v[2] +
             (w != 0 ? m[row * 4 + 3] * w : W(0));
  return r;
}

}  // namespace

DTransform toDouble(const Transform& m) {
  DTransform d;
  for (int k = 0; k < 12; ++k) d[k] = m[k];
  return d;
}

Vec3 applyAffine(const Transform& m, const Vec3& v, float w) {
  return apply(m, v, w);
}
DVec3 applyAffine(const DTransform& m, const DVec3& v, double w) {
  return apply(m, v, w);
}

}  // namespace rayspec
