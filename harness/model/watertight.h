// Watertight ray/triangle test in double precision (after Woop, Benthin and
// Wald 2013), with an error bound that says whether the decision could flip
// under the float arithmetic a device uses (then the ray is ambiguous).
#pragma once

#include <array>

namespace rayspec {

using DVec3 = std::array<double, 3>;

enum class TriAmbiguity { None, Edge, Vertex, Degenerate };

struct WatertightHit {
  bool hit = false;        // the double-precision decision (edges inclusive)
  double t = 0, b1 = 0, b2 = 0;  // barycentrics: weights of v1 and v2
  TriAmbiguity ambiguity = TriAmbiguity::None;  // near an edge / vertex
  bool valid = true;       // false: NaN somewhere (never a hit)
};

// Relative tolerance of a device's float pipeline used for the ambiguity
// bound (instance transform, shear and edge functions in float).
constexpr double kDeviceRelTolerance = 16.0 * 5.9604644775390625e-08;  // 16 * 2^-24

WatertightHit watertightIntersect(const DVec3& o, const DVec3& d, const DVec3& v0,
                                  const DVec3& v1, const DVec3& v2);

}  // namespace rayspec
