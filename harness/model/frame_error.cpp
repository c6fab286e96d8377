#include "model/frame_error.h"

#include <algorithm>
#include <cmath>

#include "base/float_steps.h"
#include "model/sphere_error.h"

namespace rayspec {

namespace {

// Roundings of a device's inverse translation (it rounds at least once) and
// of a product with a scale that is not a power of two.
constexpr double kTranslationRoundings = 2.0;
constexpr double kProductRoundings = 2.0;
// Roundings of a vertex through a geometry transform, model and device each
// in their own order (3 products, 3 sums).
constexpr double kVertexRoundings = 4.0;
// Candidate boxes are padded by this many float steps of the instance's
// translation terms (in object space): a device's origin error (2 u of the
// inverse translation for a scaled permutation, 8 u of every term for a
// general transform) and Embree's own float inverse and object-space ray
// (a few u of the same terms), for rays starting near the instance (farther
// ones: box_pad.cpp's reach term). Identity: neither rounds.
constexpr double kPadStepsPermutation = 8.0, kPadStepsGeneral = 32.0;

bool powerOfTwo(double x) {
  int e;
  return x != 0 && std::fabs(std::frexp(x, &e)) == 0.5;
}

}  // namespace

InstanceForm instanceForm(const Transform& m) {
  if (m == kIdentity) return InstanceForm::Identity;
  for (int k = 0; k < 3; ++k) {
    int row = 0, col = 0;
    for (int j = 0; j < 3; ++j) {
      row += m[k * 4 + j] != 0;
      col += m[j * 4 + k] != 0;
    }
    if (row != 1 || col != 1) return InstanceForm::General;
  }
  return InstanceForm::ScaledPermutation;
}

void objectRayFrameError(InstanceForm form, const std::array<double, 12>& inv,
                         const std::array<float, 12>& inv_f, const DVec3& o, const DVec3& d,
                         FrameError& err) {
  if (form == InstanceForm::Identity) {
    err.origin = err.direction = DVec3{};
    return;
  }
  if (form == InstanceForm::General) {
    const Vec3 of = {float(o[0]), float(o[1]), float(o[2])},
               df = {float(d[0]), float(d[1]), float(d[2])};
    const ObjectRayError e = objectRayError(inv_f, of, df);
    for (int k = 0; k < 3; ++k) {
      err.origin[k] = e.origin[k];
      err.direction[k] = e.direction[k];
    }
    return;
  }
  for (int k = 0; k < 3; ++k) {
    double eo = kTranslationRoundings * kUnitRoundoff * std::fabs(inv[k * 4 + 3]), ed = 0,
           obj = inv[k * 4 + 3];
    for (int j = 0; j < 3; ++j) {
      const double m = inv[k * 4 + j];
      if (m == 0) continue;
      obj += m * o[j];
      if (!powerOfTwo(m)) {
        eo += kProductRoundings * kUnitRoundoff * std::fabs(m * o[j]);
        ed += kProductRoundings * kUnitRoundoff * std::fabs(m * d[j]);
      }
    }
    err.origin[k] = eo + kUnitRoundoff * std::fabs(obj);
    err.direction[k] = ed;
  }
}

DVec3 geometryVertexError(const Transform& m, const std::vector<Vec3>& vertices) {
  DVec3 e{};
  if (m == kIdentity) return e;
  for (const Vec3& v : vertices)
    for (int k = 0; k < 3; ++k) {
      double s = std::fabs(m[k * 4 + 3]);
      for (int j = 0; j < 3; ++j) s += std::fabs(double(m[k * 4 + j]) * v[j]);
      if (std::isfinite(s)) e[k] = std::max(e[k], kVertexRoundings * kUnitRoundoff * s);
    }
  return e;
}

double instancePad(const std::array<double, 12>& inv, const Transform& m) {
  double pad = 0;
  for (int k = 0; k < 3; ++k) {
    double s = std::fabs(inv[k * 4 + 3]);
    for (int j = 0; j < 3; ++j) s += std::fabs(inv[k * 4 + j] * m[j * 4 + 3]);
    pad = std::max(pad, s);
  }
  const InstanceForm form = instanceForm(m);
  const double steps = form == InstanceForm::Identity            ? 0.0
                       : form == InstanceForm::ScaledPermutation ? kPadStepsPermutation
                                                                 : kPadStepsGeneral;
  return std::isfinite(pad) ? steps * kUnitRoundoff * pad : 0.0;
}

}  // namespace rayspec
