#include "model/watertight.h"

#include <cmath>

namespace rayspec {

WatertightHit watertightIntersect(const DVec3& o, const DVec3& d, const DVec3& v0,
                                  const DVec3& v1, const DVec3& v2) {
  WatertightHit r;
  // Dominant axis of the direction becomes z.
  int kz = 0;
  if (std::fabs(d[1]) > std::fabs(d[kz])) kz = 1;
  if (std::fabs(d[2]) > std::fabs(d[kz])) kz = 2;
  const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (d[kz] == 0.0 || std::isnan(d[kz])) { r.valid = false; return r; }
  const double sx = -d[kx] / d[kz], sy = -d[ky] / d[kz], sz = 1.0 / d[kz];
  const DVec3* v[3] = {&v0, &v1, &v2};
  double px[3], py[3], pz[3], mx[3], my[3];
  for (int i = 0; i < 3; ++i) {
    const double x = (*v[i])[kx] - o[kx], y = (*v[i])[ky] - o[ky], z = (*v[i])[kz] - o[kz];
    px[i] = x + sx * z;
    py[i] = y + sy * z;
    pz[i] = z * sz;
    // Magnitudes that float rounding on a device scales with.
    const double az = std::fabs((*v[i])[kz]) + std::fabs(o[kz]);
    mx[i] = std::fabs((*v[i])[kx]) + std::fabs(o[kx]) + std::fabs(sx) * az;
    my[i] = std::fabs((*v[i])[ky]) + std::fabs(o[ky]) + std::fabs(sy) * az;
  }
  double e[3], bound[3];
  for (int i = 0; i < 3; ++i) {
    const int a = (i + 1) % 3, b = (i + 2) % 3;
    e[i] = px[a] * py[b] - py[a] * px[b];
    bound[i] = kDeviceRelTolerance * (mx[a] * my[b] + my[a] * mx[b]);
  }
  for (int i = 0; i < 3; ++i)
    if (std::isnan(e[i]) || std::isnan(pz[i])) { r.valid = false; return r; }
  const bool anyNeg = e[0] < 0 || e[1] < 0 || e[2] < 0;
  const bool anyPos = e[0] > 0 || e[1] > 0 || e[2] > 0;
  // Clear sides: an edge function beyond its bound.
  const bool clearNeg = e[0] < -bound[0] || e[1] < -bound[1] || e[2] < -bound[2];
  const bool clearPos = e[0] > bound[0] || e[1] > bound[1] || e[2] > bound[2];
  const double det = e[0] + e[1] + e[2];
  const double detBound = bound[0] + bound[1] + bound[2];
  if (det != 0.0) {
    r.t = (e[0] * pz[0] + e[1] * pz[1] + e[2] * pz[2]) / det;
    r.b1 = e[1] / det;
    r.b2 = e[2] / det;
    if (std::isnan(r.t)) { r.valid = false; return r; }
  }
  r.hit = !(anyNeg && anyPos) && det != 0.0;
  if (std::fabs(det) <= detBound) {
    // Nearly edge-on or degenerate: only a problem if it could be a hit.
    if (!(clearNeg && clearPos)) r.ambiguity = TriAmbiguity::Degenerate;
    return r;
  }
  if (clearNeg && clearPos) return r;  // clearly outside
  int near = 0;
  for (int i = 0; i < 3; ++i)
    if (std::fabs(e[i]) <= bound[i]) ++near;
  if (near == 0) return r;  // clearly inside (all same sign beyond bounds)
  r.ambiguity = near >= 2 ? TriAmbiguity::Vertex : TriAmbiguity::Edge;
  return r;
}

}  // namespace rayspec
