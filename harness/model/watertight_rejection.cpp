// Proof that watertightCertainMiss never drops a triangle the full test keeps.
//
// watertightIntersect (watertight.cpp) computes, per vertex j, the translated
// sheared coordinates p_j = (x_j + s_x z_j, y_j + s_y z_j) with (x, y, z) =
// v_j - o, their error bounds
//   ex_j = vx + dsx (|z_j| + Eo_z + Ev_z) + r (|x_j| + |s_x| |z_j| + shiftX + vx)
// (ey_j likewise), and per edge (a, b) the edge function
// e = p_ax p_by - p_ay p_bx and its bound
//   bound = shiftX |p_by - p_ay| + shiftY |p_bx - p_ax|
//         + |p_ax| ey_b + |p_by| ex_a + |p_ay| ex_b + |p_bx| ey_a
//         + shiftX (ey_a + ey_b) + shiftY (ex_a + ex_b) + ex_a ey_b + ey_a ex_b
//         + r ((|p_ax| + shiftX + ex_a)(|p_by| + shiftY + ey_b) + (|p_ay| + shiftY + ey_a)(|p_bx| +
//         shiftX + ex_b)).
// Every coefficient is non-negative, so bound grows with each of |p|, ex, ey.
// With A = the largest |p_jx|, |p_jy|, X, Y, Z = the largest |x_j|, |y_j|,
// |z_j|, E = the larger of EX = ex's formula at (X, Z) and EY = ey's at
// (Y, Z) (so E >= every ex_j, ey_j) and S = max(shiftX, shiftY):
//   bound <= B = 4 S A + 4 A E + 4 S E + 2 E^2 + 2 r (A + S + E)^2
// term by term (|p_b - p_a| <= 2A, each of the four products <= A E, ...).
//
// Rounding: B and every bound are sums of products of non-negative doubles,
// at most ~30 operations, so each computed value lies within a factor
// (1 +- 30 * 2^-53) of its real value: computed bound <= computed B * (1 +
// 2^-40). The edge functions computed here and in watertightIntersect use the
// same expressions; should a compiler contract one of them into an FMA and
// not the other, each p differs by at most 2^-52 (|x| + |s_x| |z|), which
// moves e by at most 2^-52 / r (= 2^-30) of the terms |p_a| ey_b, ... of B,
// and e's own last rounding by 2^-52 * 2 A^2 <= 2^-31 * (2 r A^2) of B. So
// with the margin M = B * (1 + 2^-20) (plus the smallest subnormals, for an
// underflowing B): e < -M here implies e < -bound there, and e > M implies
// e > bound.
//
// Rejection: some edge function below -M and another above +M. Then, in
// watertightIntersect, clearNeg and clearPos both hold, the perturbed sides
// equal the (non-zero) edge functions, so anyNeg and anyPos hold: hit is
// false, and it returns before any ambiguity is set (ambiguity None). Unless
// a NaN turns up there first: then valid is false. Either way the model drops
// the triangle (ownTriangleIntersect). A NaN or an infinity here fails every
// comparison: no rejection, the full test decides.
#include "model/watertight_rejection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/float_steps.h"

namespace rayspec {

bool watertightCertainMiss(const WatertightRay& w, const DVec3& v0, const DVec3& v1,
                           const DVec3& v2, const DVec3& vertexErr) {
  if (!w.valid) return false;
  const int kx = w.kx, ky = w.ky, kz = w.kz;
  const DVec3* v[3] = {&v0, &v1, &v2};
  double px[3], py[3];
  double X = 0, Y = 0, Z = 0, A = 0;
  for (int i = 0; i < 3; ++i) {
    const double x = (*v[i])[kx] - w.o[kx], y = (*v[i])[ky] - w.o[ky], z = (*v[i])[kz] - w.o[kz];
    px[i] = x + w.sx * z;
    py[i] = y + w.sy * z;
    X = std::max(X, std::fabs(x));
    Y = std::max(Y, std::fabs(y));
    Z = std::max(Z, std::fabs(z));
    A = std::max({A, std::fabs(px[i]), std::fabs(py[i])});
  }
  bool neg = false, pos = false;
  double e[3];
  for (int i = 0; i < 3; ++i) {
    const int a = (i + 1) % 3, b = (i + 2) % 3;
    e[i] = px[a] * py[b] - py[a] * px[b];
  }
  const double round = kFrameRoundings * kUnitRoundoff;
  const double vx = vertexErr[kx] + std::fabs(w.sx) * vertexErr[kz];
  const double vy = vertexErr[ky] + std::fabs(w.sy) * vertexErr[kz];
  const double az = Z + w.origin_err[kz] + vertexErr[kz];
  const double EX = vx + w.dsx * az + round * (X + std::fabs(w.sx) * Z + w.shiftX + vx);
  const double EY = vy + w.dsy * az + round * (Y + std::fabs(w.sy) * Z + w.shiftY + vy);
  const double E = std::max(EX, EY), S = std::max(w.shiftX, w.shiftY);
  const double ase = A + S + E;
  const double B = 4 * S * A + 4 * A * E + 4 * S * E + 2 * E * E + 2 * round * ase * ase;
  const double M = B * (1 + 0x1p-20) + 64 * std::numeric_limits<double>::denorm_min();
  for (double x : e) {
    neg = neg || x < -M;
    pos = pos || x > M;
  }
  return neg && pos;
}

}  // namespace rayspec
