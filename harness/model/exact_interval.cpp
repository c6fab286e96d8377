#include "model/exact_interval.h"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>

namespace rayspec {

namespace {

// Exponents kept far from float's range ends: products of three grid values
// and a power-of-two direction neither overflow nor lose bits to subnormals.
constexpr int kGridExponentLimit = 30;
constexpr int kDirectionExponentLimit = 20;

// The smallest grid (multiples of 2^lo, magnitudes up to 2^hi) that holds
// every value added; `ok` turns false for a value that is no float.
struct Grid {
  int lo = INT_MAX, hi = INT_MIN;
  bool ok = true;
  void add(double x) {
    if (!ok) return;
    if (!std::isfinite(x) || static_cast<double>(static_cast<float>(x)) != x) {
      ok = false;
      return;
    }
    if (x == 0) return;
    int e;
    const double m = std::frexp(std::fabs(x), &e);  // |x| = m * 2^e, m in [0.5, 1)
    const uint64_t bits = static_cast<uint64_t>(std::ldexp(m, 53));
    lo = std::min(lo, e - 53 + std::countr_zero(bits));
    hi = std::max(hi, m == 0.5 ? e - 1 : e);
  }
  bool fits() const {
    if (!ok) return false;
    if (lo == INT_MAX) return true;  // only zeros
    return hi - lo <= kExactGridBits && lo >= -kGridExponentLimit && hi <= kGridExponentLimit;
  }
};

// A power of two (either sign) within the exponent limit.
bool exactScale(double x, int limit) {
  int e;
  return x != 0 && std::isfinite(x) && std::fabs(std::frexp(x, &e)) == 0.5 && std::abs(e - 1) <= limit;
}

}  // namespace

bool objectRayExact(InstanceForm form, const Transform& m, const DVec3& o) {
  if (form == InstanceForm::Identity) return true;
  if (form != InstanceForm::ScaledPermutation) return false;
  Grid g;
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j < 3; ++j)
      if (m[k * 4 + j] != 0 && !exactScale(m[k * 4 + j], kDirectionExponentLimit)) return false;
    g.add(m[k * 4 + 3]);
    g.add(o[k]);
  }
  return g.fits();
}

ExactEnds exactEnds(const DVec3& o, const DVec3& d, const DVec3& v0, const DVec3& v1, const DVec3& v2, double t,
                    double tmin, double tmax) {
  ExactEnds r;
  int axis = -1;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) continue;
    if (axis >= 0 || !exactScale(d[k], kDirectionExponentLimit)) return r;
    axis = k;
  }
  if (axis < 0 || v0[axis] != v1[axis] || v0[axis] != v2[axis]) return r;
  Grid g;
  for (int k = 0; k < 3; ++k) {
    g.add(o[k]);
    g.add(v0[k]);
    g.add(v1[k]);
    g.add(v2[k]);
  }
  g.add(t);
  if (!g.fits()) return r;
  // At or beyond an end the comparison is exact whatever the end's grid;
  // inside it, only when the end is on the grid too.
  Grid withMin = g, withMax = g;
  withMin.add(tmin);
  withMax.add(tmax);
  r.tmin = t <= tmin || withMin.fits();
  r.tmax = t >= tmax || withMax.fits();
  return r;
}

}  // namespace rayspec
