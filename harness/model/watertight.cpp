#include "model/watertight.h"

#include <algorithm>
#include <cmath>

#include "base/float_steps.h"
#include "model/in_plane.h"

namespace rayspec {

namespace {

// The sign of the edge function of (a, b) for the origin moved by (eps,
// eps^2): e(eps) = e - eps (p_by - p_ay) + eps^2 (p_bx - p_ax). Swapping a
// and b negates it exactly (the same differences, negated). 0 only for an
// edge of zero length.
double perturbedSide(const double* px, const double* py, int a, int b) {
  const double dy = py[b] - py[a];
  if (dy != 0.0) return -dy;
  return px[b] - px[a];
}

}  // namespace

WatertightRay prepareWatertightRay(const DVec3& o, const DVec3& d, const FrameError& err) {
  WatertightRay w;
  w.o = o;
  w.d = d;
  w.origin_err = err.origin;
  w.direction_err = err.direction;
  // Dominant axis of the direction becomes z.
  int kz = 0;
  if (std::fabs(d[1]) > std::fabs(d[kz])) kz = 1;
  if (std::fabs(d[2]) > std::fabs(d[kz])) kz = 2;
  const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  w.kx = kx;
  w.ky = ky;
  w.kz = kz;
  if (d[kz] == 0.0 || std::isnan(d[kz])) return w;
  w.valid = true;
  w.sx = -d[kx] / d[kz];
  w.sy = -d[ky] / d[kz];
  w.sz = 1.0 / d[kz];
  const double round = kFrameRoundings * kUnitRoundoff;
  // The shear a device derives from its own direction.
  w.dsx = round * std::fabs(w.sx) +
          (err.direction[kx] + std::fabs(w.sx) * err.direction[kz]) / std::fabs(d[kz]);
  w.dsy = round * std::fabs(w.sy) +
          (err.direction[ky] + std::fabs(w.sy) * err.direction[kz]) / std::fabs(d[kz]);
  // The device's origin error, sheared: one shift of all three vertices.
  w.shift_x = err.origin[kx] + std::fabs(w.sx) * err.origin[kz];
  w.shift_y = err.origin[ky] + std::fabs(w.sy) * err.origin[kz];
  w.dir_err = err.direction[kz] / std::fabs(d[kz]) + round;
  return w;
}

WatertightHit watertightIntersect(const DVec3& o, const DVec3& d, const DVec3& v0, const DVec3& v1,
                                  const DVec3& v2, const FrameError& err) {
  return watertightIntersectPrepared(prepareWatertightRay(o, d, err), v0, v1, v2, err.vertex);
}

namespace {

// The triangle in the ray's sheared frame (origin at 0, ray along +z), and
// each vertex's error bound there.
struct ShearedTriangle {
  double px[3], py[3], pz[3], ex[3], ey[3];
};

ShearedTriangle shearTriangle(const WatertightRay& w, const DVec3* const v[3],
                              const DVec3& vertex_err) {
  const DVec3& o = w.o;
  const int kx = w.kx, ky = w.ky, kz = w.kz;
  const double sx = w.sx, sy = w.sy, sz = w.sz, dsx = w.dsx, dsy = w.dsy, shift_x = w.shift_x,
               shift_y = w.shift_y;
  const double round = kFrameRoundings * kUnitRoundoff;
  ShearedTriangle s;
  for (int i = 0; i < 3; ++i) {
    const double x = (*v[i])[kx] - o[kx], y = (*v[i])[ky] - o[ky], z = (*v[i])[kz] - o[kz];
    s.px[i] = x + sx * z;
    s.py[i] = y + sy * z;
    s.pz[i] = z * sz;
    // Per vertex: the vertex error through the shear, the shear's own error
    // along this vertex's depth, and the rounding of the translated, sheared
    // coordinate relative to its magnitude.
    const double vx = vertex_err[kx] + std::fabs(sx) * vertex_err[kz];
    const double vy = vertex_err[ky] + std::fabs(sy) * vertex_err[kz];
    const double az = std::fabs(z) + w.origin_err[kz] + vertex_err[kz];
    s.ex[i] = vx + dsx * az + round * (std::fabs(x) + std::fabs(sx) * std::fabs(z) + shift_x + vx);
    s.ey[i] = vy + dsy * az + round * (std::fabs(y) + std::fabs(sy) * std::fabs(z) + shift_y + vy);
  }
  return s;
}

// The edge functions e[i] (of the edge opposite vertex i) and the bound on
// how far a device's may differ.
void edgeFunctions(const WatertightRay& w, const ShearedTriangle& s, double e[3], double bound[3]) {
  const double shift_x = w.shift_x, shift_y = w.shift_y;
  const double round = kFrameRoundings * kUnitRoundoff;
  const double *px = s.px, *py = s.py, *ex = s.ex, *ey = s.ey;
  for (int i = 0; i < 3; ++i) {
    const int a = (i + 1) % 3, b = (i + 2) % 3;
    e[i] = px[a] * py[b] - py[a] * px[b];
    const double ax = std::fabs(px[a]), ay = std::fabs(py[a]), bx = std::fabs(px[b]),
                 by = std::fabs(py[b]);
    bound[i] = shift_x * std::fabs(py[b] - py[a]) + shift_y * std::fabs(px[b] - px[a]) +
               ax * ey[b] + by * ex[a] + ay * ex[b] + bx * ey[a] + shift_x * (ey[a] + ey[b]) +
               shift_y * (ex[a] + ex[b]) + ex[a] * ey[b] + ey[a] * ex[b] +
               round * ((ax + shift_x + ex[a]) * (by + shift_y + ey[b]) +
                        (ay + shift_y + ey[a]) * (bx + shift_x + ex[b]));
  }
}

// t, the barycentrics and t's error bound, where det (the sum of the edge
// functions) is not 0. False when t is NaN.
bool solveHit(const WatertightRay& w, const DVec3* const v[3], const DVec3& vertex_err,
              const ShearedTriangle& s, const double e[3], const double bound[3], double det,
              WatertightHit& r) {
  const int kz = w.kz;
  const double round = kFrameRoundings * kUnitRoundoff;
  r.t = (e[0] * s.pz[0] + e[1] * s.pz[1] + e[2] * s.pz[2]) / det;
  r.b1 = e[1] / det;
  r.b2 = e[2] / det;
  if (std::isnan(r.t)) return false;
  const double dir_err = w.dir_err;
  double t_err = 0, depth_err = 0;
  for (int i = 0; i < 3; ++i) {
    const double az = std::fabs((*v[i])[kz] - w.o[kz]);
    t_err += bound[i] * std::fabs(s.pz[i] - r.t);
    depth_err =
        std::max(depth_err, (w.origin_err[kz] + vertex_err[kz] + round * az) * std::fabs(w.sz) +
                                dir_err * std::fabs(s.pz[i]));
  }
  r.t_err = t_err / std::fabs(det) + depth_err;
  if (!std::isfinite(r.t_err)) r.t_err = 0;
  return true;
}

// A determinant of no sure sign: the ray's line nearly in the triangle's
// plane (the triangle seen edge-on, to rounding). A watertight device takes
// det as the sum of the edge functions and tests their signs alone, but a
// device may compute det apart from them (Moller-Trumbore: det = E1 . (D x
// E2), the barycentrics T . P / det and D . Q / det tested against 0 and 1,
// by a division or a reciprocal's product, fused or not): a det of the
// other sign turns its inside into the cone opposite a vertex, a det near 0
// makes its barycentrics and t ratios of rounding. So no sign of an edge
// function is sure there, however clear: a hit on either face anywhere along
// the line's near-overlap with the triangle is legal, and so is none
// (in_plane.h; lavapipe 25.0.7 and Mesa 26.2.6 hit such rays).
bool nearlyInPlane(double det, const double bound[3]) {
  return det != 0.0 && std::fabs(det) <= bound[0] + bound[1] + bound[2];
}

// Edge functions within their bound: one is an edge, two meeting at a vertex
// (the third clear) is that vertex, three is no shape at all; nearly edge-on
// or degenerate, a device may see no triangle at all.
TriAmbiguity nearEdges(const double e[3], const double bound[3], double det) {
  const double det_bound = bound[0] + bound[1] + bound[2];
  int near = 0;
  for (int i = 0; i < 3; ++i)
    if (std::fabs(e[i]) <= bound[i]) ++near;
  if (near == 2 && det != 0.0) return TriAmbiguity::Vertex;
  if (std::fabs(det) <= det_bound || near == 3) return TriAmbiguity::Degenerate;
  if (near == 1) return TriAmbiguity::Edge;
  return TriAmbiguity::None;
}

}  // namespace

WatertightHit watertightIntersectPrepared(const WatertightRay& w, const DVec3& v0, const DVec3& v1,
                                          const DVec3& v2, const DVec3& vertex_err) {
  WatertightHit r;
  if (!w.valid) {
    r.valid = false;
    return r;
  }
  const DVec3* v[3] = {&v0, &v1, &v2};
  const ShearedTriangle s = shearTriangle(w, v, vertex_err);
  double e[3], bound[3];
  edgeFunctions(w, s, e, bound);
  for (int i = 0; i < 3; ++i)
    if (std::isnan(e[i]) || std::isnan(s.pz[i]) || std::isnan(bound[i])) {
      r.valid = false;
      return r;
    }
  // The hit decision: an edge function of exactly zero (the ray through the
  // edge in double precision) takes the sign it has for the origin moved by
  // (eps, eps^2) in the sheared plane, eps -> 0 (a symbolic perturbation):
  // the two triangles of a shared edge compute that edge from the same two
  // points in opposite order, so exactly one of them (one triangle of a
  // closed fan around a vertex) counts the ray as inside. A watertight
  // device hits one of them; the model does the same.
  double side[3];
  for (int i = 0; i < 3; ++i)
    side[i] = e[i] != 0.0 ? e[i] : perturbedSide(s.px, s.py, (i + 1) % 3, (i + 2) % 3);
  const bool any_neg = side[0] < 0 || side[1] < 0 || side[2] < 0;
  const bool any_pos = side[0] > 0 || side[1] > 0 || side[2] > 0;
  // Clear sides: an edge function beyond its bound.
  const bool clear_neg = e[0] < -bound[0] || e[1] < -bound[1] || e[2] < -bound[2];
  const bool clear_pos = e[0] > bound[0] || e[1] > bound[1] || e[2] > bound[2];
  const double det = e[0] + e[1] + e[2];
  if (det != 0.0 && !solveHit(w, v, vertex_err, s, e, bound, det, r)) {
    r.valid = false;
    return r;
  }
  r.hit = !(any_neg && any_pos) && det != 0.0;
  const bool near_plane = nearlyInPlane(det, bound);
  if (clear_neg && clear_pos && !near_plane) return r;  // clearly outside
  // Every edge function within its bound: the triangle seen edge-on with the
  // origin on its line, the ray in its plane whether det is 0 or a rounding
  // off it (the model's own object-space ray through a double inverse that
  // is not exact: fuzz/seed-120327), where the line lies near the plane
  // (not a ray from far away whose frame error covers the whole triangle:
  // fuzz/seed-120531, a degenerate candidate as before).
  const bool all_near =
      std::fabs(e[0]) <= bound[0] && std::fabs(e[1]) <= bound[1] && std::fabs(e[2]) <= bound[2];
  r.in_plane = (det == 0.0 && all_near) || (near_plane && clear_neg && clear_pos) ||
               (near_plane && all_near && lineNearPlane(w, v0, v1, v2, vertex_err));
  r.hit = r.hit && !r.in_plane;  // the model's own answer there: no hit (in_plane.h)
  r.ambiguity = nearEdges(e, bound, det);
  for (int i = 0; i < 3; ++i)
    if (std::fabs(e[i]) <= bound[i]) r.near_edges |= static_cast<uint8_t>(1u << i);
  return r;
}

}  // namespace rayspec
