// First-order propagation of the object-ray error through the float formulas
// of sphereRoots (model_shading.cpp), plus each operation's own rounding and
// the second-order products, all in double with magnitudes.
#include "model/sphere_error.h"

#include <algorithm>
#include <cmath>

namespace rayspec {

namespace {

constexpr double kU = 5.9604644775390625e-08;  // 2^-24, float unit roundoff
// Roundings allowed to the device's object ray: its inverse of the transform
// (a few operations) and the transform itself (3 products, 3 sums).
constexpr double kObjectRoundings = 8.0;

}  // namespace

ObjectRayError objectRayError(const std::array<float, 12>& m, const F3& o, const F3& d) {
  ObjectRayError e;
  for (int k = 0; k < 3; ++k) {
    double so = std::fabs(m[k * 4 + 3]), sd = 0;
    for (int j = 0; j < 3; ++j) {
      so += std::fabs(m[k * 4 + j]) * std::fabs(o[j]);
      sd += std::fabs(m[k * 4 + j]) * std::fabs(d[j]);
    }
    e.origin[k] = static_cast<float>(kObjectRoundings * kU * so);
    e.direction[k] = static_cast<float>(kObjectRoundings * kU * sd);
  }
  return e;
}

SphereError sphereError(const F3& bmin, const F3& bmax, const F3& o, const F3& d, const ObjectRayError& e) {
  double c[3], h[3], oc[3], eoc[3];
  for (int k = 0; k < 3; ++k) {
    c[k] = (double(bmin[k]) + bmax[k]) * 0.5;
    h[k] = (double(bmax[k]) - bmin[k]) * 0.5;
  }
  const double r = std::min({h[0], h[1], h[2]});
  for (int k = 0; k < 3; ++k) {
    oc[k] = double(o[k]) - c[k];
    eoc[k] = e.origin[k] + kU * (std::fabs(o[k]) + std::fabs(c[k]));
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
  ea += 3 * kU * a;
  eb += 3 * kU * babs;
  ecc += 4 * kU * ccabs;
  SphereError s;
  s.disc = b * b - a * cc;
  s.disc_err = 2 * std::fabs(b) * eb + eb * eb + std::fabs(a) * ecc + std::fabs(cc) * ea + ea * ecc +
               2 * kU * (b * b + std::fabs(a * cc)) + 2 * kU * std::fabs(s.disc);
  if (!(a > 0)) {
    s.near_err = s.far_err = INFINITY;
    return s;
  }
  // The square root over every discriminant within the bound.
  const double sq = std::sqrt(std::max(s.disc, 0.0));
  const double es = std::max(std::sqrt(std::max(s.disc, 0.0) + s.disc_err) - sq,
                             sq - std::sqrt(std::max(s.disc - s.disc_err, 0.0))) + kU * sq;
  for (int sign : {-1, 1}) {
    const double t = (-b + sign * sq) / a;
    const double err = (eb + es) / a + std::fabs(t) * ea / a + 3 * kU * (std::fabs(t) + (std::fabs(b) + sq) / a);
    (sign < 0 ? s.near_err : s.far_err) = err;
  }
  return s;
}

}  // namespace rayspec
