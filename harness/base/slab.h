// The slab test: where a ray's line o + t d lies inside an axis-aligned box.
#pragma once

#include <limits>

#include "base/vec3.h"

namespace rayspec {

// An interval of t; empty unless t0 <= t1 (NaN ends make it empty).
struct Span {
  double t0 = -std::numeric_limits<double>::infinity();
  double t1 = std::numeric_limits<double>::infinity();
  bool empty() const { return !(t0 <= t1); }
};

// The part of `within` where o + t d lies in the box [lo, hi] (faces
// included). An axis the ray runs parallel to (d = 0) keeps the whole span
// when o lies between the faces and empties it otherwise. A NaN in o or d
// drops that axis's constraint: callers rule such rays out first.
Span slabSpan(const DVec3& lo, const DVec3& hi, const DVec3& o, const DVec3& d, Span within = {});

}  // namespace rayspec
