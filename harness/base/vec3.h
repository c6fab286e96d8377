// Three-component vectors: Vec3 (float, as cases and devices hold them) and
// DVec3 (double, as the model and the case tools compute), and the few
// operations the harness needs on them.
#pragma once

#include <array>

namespace rayspec {

using Vec3 = std::array<float, 3>;
using DVec3 = std::array<double, 3>;

DVec3 toDouble(const Vec3& v);
Vec3 toFloat(const DVec3& v);  // each component rounded to nearest

DVec3 sub(const DVec3& a, const DVec3& b);
DVec3 cross(const DVec3& a, const DVec3& b);
double dot(const DVec3& a, const DVec3& b);
double length(const DVec3& a);
double largestMagnitude(const DVec3& a);  // the infinity norm: max |a_k|
DVec3 scaled(const DVec3& a, double s);
DVec3 axpy(const DVec3& p, const DVec3& u, double s);  // p + u s

}  // namespace rayspec
