#include "base/vec3.h"

#include <algorithm>
#include <cmath>

namespace rayspec {

DVec3 toDouble(const Vec3& v) {
  return {v[0], v[1], v[2]};
}

Vec3 toFloat(const DVec3& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

DVec3 sub(const DVec3& a, const DVec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

DVec3 cross(const DVec3& a, const DVec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double dot(const DVec3& a, const DVec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double length(const DVec3& a) {
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

double largestMagnitude(const DVec3& a) {
  return std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2])});
}

DVec3 scaled(const DVec3& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}

DVec3 axpy(const DVec3& p, const DVec3& u, double s) {
  return {p[0] + u[0] * s, p[1] + u[1] * s, p[2] + u[2] * s};
}

}  // namespace rayspec
