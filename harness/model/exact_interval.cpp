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
  return x != 0 && std::isfinite(x) && std::fabs(std::frexp(x, &e)) == 0.5 &&
         std::abs(e - 1) <= limit;
}

// A device that multiplies by a rounded reciprocal instead of dividing: with
// the direction on `axis` and the triangle perpendicular to it, every form of
// t's numerator and denominator is A * (v - o) and A * d up to powers of two,
// A the doubled area of the triangle's projection (exact on the grid). Then t
// comes out as (A * (v - o)) * rcp(A) / d. Exact when A is a power of two
// (every reciprocal of it is exact), or when that is t for the correctly
// rounded reciprocal and for one a float step off either way.
bool rcpMultiplyExact(const DVec3& o, const DVec3& d, const DVec3& v0, const DVec3& v1,
                      const DVec3& v2, int axis, double t) {
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  const float area = static_cast<float>(
      std::fabs((v1[a] - v0[a]) * (v2[b] - v0[b]) - (v1[b] - v0[b]) * (v2[a] - v0[a])));
  if (area == 0) return true;  // no hit to judge
  int e;
  if (std::frexp(area, &e) == 0.5f) return true;  // a power of two: every reciprocal is exact
  const float delta = static_cast<float>(v0[axis] - o[axis]);
  const float numerator = area * delta;  // exact on the grid
  const float rcp = 1.0f / area;
  for (const float r : {rcp, std::nextafter(rcp, 0.0f), std::nextafter(rcp, 2 * rcp)}) {
    const float scaled = numerator * r;
    if (static_cast<double>(scaled) / d[axis] != t) return false;
  }
  return true;
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

ExactEnds exactEnds(const DVec3& o, const DVec3& d, const DVec3& v0, const DVec3& v1,
                    const DVec3& v2, double t, double tmin, double tmax) {
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
  if (!g.fits() || !rcpMultiplyExact(o, d, v0, v1, v2, axis, t)) return r;
  // At or beyond an end the comparison is exact whatever the end's grid;
  // inside it, only when the end is on the grid too.
  Grid with_min = g, with_max = g;
  with_min.add(tmin);
  with_max.add(tmax);
  r.tmin = t <= tmin || with_min.fits();
  r.tmax = t >= tmax || with_max.fits();
  return r;
}

}  // namespace rayspec
