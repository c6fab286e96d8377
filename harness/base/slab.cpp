#include "base/slab.h"

#include <algorithm>
#include <utility>

namespace rayspec {

Span slabSpan(const DVec3& lo, const DVec3& hi, const DVec3& o, const DVec3& d, Span within) {
  Span s = within;
  for (int k = 0; k < 3 && !s.empty(); ++k) {
    if (d[k] == 0.0) {
      if (o[k] < lo[k] || o[k] > hi[k]) return {1, 0};
      continue;
    }
    double ta = (lo[k] - o[k]) / d[k], tb = (hi[k] - o[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    s.t0 = std::max(s.t0, ta);
    s.t1 = std::min(s.t1, tb);
  }
  return s;
}

}  // namespace rayspec
