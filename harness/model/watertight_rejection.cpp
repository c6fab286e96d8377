// Proof that watertightCertainMiss never drops a triangle the full test keeps.
//
// watertightIntersect (watertight.cpp) computes, per vertex j, the translated
// sheared coordinates p_j = (x_j + s_x z_j, y_j + s_y z_j) with (x, y, z) =
// v_j - o, their error bounds
//   ex_j = vx + dsx (|z_j| + Eo_z + Ev_z) + r (|x_j| + |s_x| |z_j| + shift_x + vx)
// (ey_j likewise), and per edge (a, b) the edge function
// e = p_ax p_by - p_ay p_bx and its bound
//   bound = shift_x |p_by - p_ay| + shift_y |p_bx - p_ax|
//         + |p_ax| ey_b + |p_by| ex_a + |p_ay| ex_b + |p_bx| ey_a
//         + shift_x (ey_a + ey_b) + shift_y (ex_a + ex_b) + ex_a ey_b + ey_a ex_b
//         + r ((|p_ax| + shift_x + ex_a)(|p_by| + shift_y + ey_b) + (|p_ay| + shift_y +
//         ey_a)(|p_bx| + shift_x + ex_b)).
// Every coefficient is non-negative, so bound grows with each of |p|, ex, ey.
// With A = the largest |p_jx|, |p_jy|, X, Y, Z = the largest |x_j|, |y_j|,
// |z_j|, E = the larger of EX = ex's formula at (X, Z) and EY = ey's at
// (Y, Z) (so E >= every ex_j, ey_j) and S = max(shift_x, shift_y):
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
// Rejection: some edge function below -M and another above +M, and their
// sum det beyond 3 M (1 + 2^-20). Then, in watertightIntersect, clear_neg and
// clear_pos both hold, the perturbed sides equal the (non-zero) edge
// functions, so any_neg and any_pos hold: hit is false; its det (the same
// sum, of edge functions within 2^-30 B each of these, rounded alike) lies
// beyond the sum of the three bounds (each <= B (1 + 2^-40)), so the ray is
// not nearly in the plane (nearlyInPlane), and it returns before any
// ambiguity is set (ambiguity None). Unless
// a NaN turns up there first: then valid is false. Either way the model drops
// the triangle (ownTriangleIntersect). A NaN or an infinity here fails every
// comparison: no rejection, the full test decides.
//
// In the code: A is max_p; X, Y, Z are max_x, max_y, max_z; EX, EY, E are
// err_x, err_y, err; S is shift; B is b_sum; M is margin.
#include "model/watertight_rejection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/float_steps.h"

namespace rayspec {

bool watertightCertainMiss(const WatertightRay& w, const DVec3& v0, const DVec3& v1,
                           const DVec3& v2, const DVec3& vertex_err) {
  if (!w.valid) return false;
  const int kx = w.kx, ky = w.ky, kz = w.kz;
  const DVec3* v[3] = {&v0, &v1, &v2};
  double px[3], py[3];
  double max_x = 0, max_y = 0, max_z = 0, max_p = 0;
  for (int i = 0; i < 3; ++i) {
    const double x = (*v[i])[kx] - w.o[kx], y = (*v[i])[ky] - w.o[ky], z = (*v[i])[kz] - w.o[kz];
    px[i] = x + w.sx * z;
    py[i] = y + w.sy * z;
    max_x = std::max(max_x, std::fabs(x));
    max_y = std::max(max_y, std::fabs(y));
    max_z = std::max(max_z, std::fabs(z));
    max_p = std::max({max_p, std::fabs(px[i]), std::fabs(py[i])});
  }
  bool neg = false, pos = false;
  double e[3];
  for (int i = 0; i < 3; ++i) {
    const int a = (i + 1) % 3, b = (i + 2) % 3;
    e[i] = px[a] * py[b] - py[a] * px[b];
  }
  const double round = kFrameRoundings * kUnitRoundoff;
  const double vx = vertex_err[kx] + std::fabs(w.sx) * vertex_err[kz];
  const double vy = vertex_err[ky] + std::fabs(w.sy) * vertex_err[kz];
  const double az = max_z + w.origin_err[kz] + vertex_err[kz];
  const double err_x = vx + w.dsx * az + round * (max_x + std::fabs(w.sx) * max_z + w.shift_x + vx);
  const double err_y = vy + w.dsy * az + round * (max_y + std::fabs(w.sy) * max_z + w.shift_y + vy);
  const double err = std::max(err_x, err_y), shift = std::max(w.shift_x, w.shift_y);
  const double ase = max_p + shift + err;
  const double b_sum =
      4 * shift * max_p + 4 * max_p * err + 4 * shift * err + 2 * err * err + 2 * round * ase * ase;
  const double margin = b_sum * (1 + 0x1p-20) + 64 * std::numeric_limits<double>::denorm_min();
  for (double x : e) {
    neg = neg || x < -margin;
    pos = pos || x > margin;
  }
  return neg && pos && std::fabs(e[0] + e[1] + e[2]) > 3 * margin * (1 + 0x1p-20);
}

}  // namespace rayspec
