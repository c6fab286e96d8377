#include "model/in_plane.h"

#include <algorithm>
#include <cmath>

namespace rayspec {

namespace {

// How far, in the plane, a device's line and triangle may lie from the
// model's (in_plane.h).
double planeSlack(const WatertightRay& w, const DVec3* const v[3], const DVec3& vertex_err) {
  double reach = 0;  // S: the largest translated coordinate
  for (int j = 0; j < 3; ++j) reach = std::max(reach, largestMagnitude(sub(*v[j], w.o)));
  return kDeviceRelTolerance * reach + largestMagnitude(w.origin_err) +
         reach / largestMagnitude(w.d) * largestMagnitude(w.direction_err) +
         largestMagnitude(vertex_err);
}

// Every device sees the ray exactly in the plane: its object ray and
// vertices are the model's (no frame error), and the plane is a coordinate
// plane the ray runs in (the vertices' and the origin's coordinate across it
// equal, the direction's 0): each product across it is exactly 0 whatever
// the algorithm (precision/grazing-rays' rays in z = 0).
bool exactlyInPlane(const WatertightRay& w, const DVec3* const v[3], const DVec3& n,
                    const DVec3& vertex_err) {
  if (largestMagnitude(w.origin_err) > 0 || largestMagnitude(w.direction_err) > 0 ||
      largestMagnitude(vertex_err) > 0)
    return false;
  int axis = -1;
  for (int k = 0; k < 3; ++k)
    if (n[k] != 0) {
      if (axis >= 0) return false;
      axis = k;
    }
  return axis >= 0 && w.d[axis] == 0 && (*v[0])[axis] == w.o[axis] && (*v[1])[axis] == w.o[axis] &&
         (*v[2])[axis] == w.o[axis];
}

}  // namespace

bool lineNearPlane(const WatertightRay& w, const DVec3& v0, const DVec3& v1, const DVec3& v2,
                   const DVec3& vertex_err) {
  const DVec3* const v[3] = {&v0, &v1, &v2};
  const DVec3 n = cross(sub(v1, v0), sub(v2, v0));
  const double area = length(n), dn = largestMagnitude(w.d);
  if (!(area > 0) || !std::isfinite(area) || !(dn > 0)) return false;
  double reach = 0;
  for (int j = 0; j < 3; ++j) reach = std::max(reach, largestMagnitude(sub(*v[j], w.o)));
  const double slack = planeSlack(w, v, vertex_err);
  return std::fabs(dot(sub(w.o, v0), n)) / area <= slack &&
         std::fabs(dot(w.d, n)) / area * (reach / dn) <= slack;
}

std::optional<Span> inPlaneSpan(const WatertightRay& w, const DVec3& v0, const DVec3& v1,
                                const DVec3& v2, const DVec3& vertex_err) {
  const DVec3* const v[3] = {&v0, &v1, &v2};
  const DVec3 n = cross(sub(v1, v0), sub(v2, v0));
  const double area = length(n);
  if (!(area > 0) || !std::isfinite(area) || !(largestMagnitude(w.d) > 0) ||
      exactlyInPlane(w, v, n, vertex_err))
    return std::nullopt;
  const double slack = planeSlack(w, v, vertex_err);
  // Each edge (a, b): the line's signed distance in the plane from the
  // edge's line, inside positive, is s0 + t s1; the grown triangle keeps
  // s0 + t s1 >= -slack.
  Span s;
  for (int i = 0; i < 3 && !s.empty(); ++i) {
    const DVec3& a = *v[i];
    const DVec3 edge = sub(*v[(i + 1) % 3], a);
    const double norm = length(edge) * area;
    const double s0 = dot(cross(edge, sub(w.o, a)), n) / norm;
    const double s1 = dot(cross(edge, w.d), n) / norm;
    if (s1 == 0.0) {
      if (s0 < -slack) return Span{1, 0};  // runs beside the edge, outside
      continue;
    }
    const double t = (-slack - s0) / s1;
    if (s1 > 0)
      s.t0 = std::max(s.t0, t);
    else
      s.t1 = std::min(s.t1, t);
  }
  return s;
}

}  // namespace rayspec
