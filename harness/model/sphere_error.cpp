// First-order propagation of the object-ray error through the float formulas
// of sphereRoots (model_shading.cpp), plus each operation's own rounding and
// the second-order products, all in double with magnitudes.
#include "model/sphere_error.h"

#include <algorithm>
#include <cmath>

#include "base/float_steps.h"

namespace rayspec {

namespace {

// Roundings allowed to the device's object ray: its inverse of the transform
// (a few operations) and the transform itself (3 products, 3 sums).
constexpr double kObjectRoundings = 8.0;

}  // namespace

ObjectRayError objectRayError(const std::array<float, 12>& m, const Vec3& o, const Vec3& d) {
  ObjectRayError e;
  for (int k = 0; k < 3; ++k) {
    double so = std::fabs(m[k * 4 + 3]), sd = 0;
    for (int j = 0; j < 3; ++j) {
      so += std::fabs(m[k * 4 + j]) * std::fabs(o[j]);
      sd += std::fabs(m[k * 4 + j]) * std::fabs(d[j]);
    }
    e.origin[k] = static_cast<float>(kObjectRoundings * kUnitRoundoff * so);
    e.direction[k] = static_cast<float>(kObjectRoundings * kUnitRoundoff * sd);
  }
  return e;
}

SphereError sphereError(const Vec3& bmin, const Vec3& bmax, const Vec3& o, const Vec3& d,
                        const ObjectRayError& e) {
  double c[3], h[3], oc[3], eoc[3];
  for (int k = 0; k < 3; ++k) {
    c[k] = (double(bmin[k]) + bmax[k]) * 0.5;
    h[k] = (double(bmax[k]) - bmin[k]) * 0.5;
  }
  const double r = std::min({h[0], h[1], h[2]});
  for (int k = 0; k < 3; ++k) {
    oc[k] = double(o[k]) - c[k];
    eoc[k] = e.origin[k] + kUnitRoundoff * (std::fabs(o[k]) + std::fabs(c[k]));
  }
  double a = 0, b = 0, cc = -r * r, ea = 0, eb = 0, ecc = 0, babs = 0, ccabs = r * r;
  for (int k = 0; k < 3; ++k) {
    const double dk = d[k], edk = e.direction[k];
    a += dk * dk;
    b += oc[k] * dk;
    cc += oc[k] * oc[k];
    babs += std::fabs(oc[k] * dk);
    ccabs += oc[k] * oc[k];
    ea += 2 * std::fabs(dk) * edk + edk * edk;
    eb += std::fabs(oc[k]) * edk + std::fabs(dk) * eoc[k] + eoc[k] * edk;
    ecc += 2 * std::fabs(oc[k]) * eoc[k] + eoc[k] * eoc[k];
  }
  ea += 3 * kUnitRoundoff * a;
  eb += 3 * kUnitRoundoff * babs;
  ecc += 4 * kUnitRoundoff * ccabs;
  SphereError s;
  s.disc = b * b - a * cc;
  s.disc_err = 2 * std::fabs(b) * eb + eb * eb + std::fabs(a) * ecc + std::fabs(cc) * ea +
               ea * ecc + 2 * kUnitRoundoff * (b * b + std::fabs(a * cc)) +
               2 * kUnitRoundoff * std::fabs(s.disc);
  if (!(a > 0)) {
    s.near_err = s.far_err = INFINITY;
    return s;
  }
  // The square root over every discriminant within the bound.
  const double sq = std::sqrt(std::max(s.disc, 0.0));
  const double es = std::max(std::sqrt(std::max(s.disc, 0.0) + s.disc_err) - sq,
                             sq - std::sqrt(std::max(s.disc - s.disc_err, 0.0))) +
                    kUnitRoundoff * sq;
  for (int sign : {-1, 1}) {
    const double t = (-b + sign * sq) / a;
    const double err = (eb + es) / a + std::fabs(t) * ea / a +
                       3 * kUnitRoundoff * (std::fabs(t) + (std::fabs(b) + sq) / a);
    (sign < 0 ? s.near_err : s.far_err) = err;
  }
  return s;
}

}  // namespace rayspec
