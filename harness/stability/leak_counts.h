// Leaks and double hits of one run of a stability case, against geometric
// truth: every ray of a stability case crosses one planar, single-layer mesh
// strictly inside its outline (rays: aim), through non-opaque triangles with
// NO_DUPLICATE_ANY_HIT_INVOCATION whose any-hit ignores every candidate, so
// a watertight implementation runs any-hit exactly once per ray. None is a
// leak, more than one a double hit (R-WATERTIGHT).
#pragma once

#include <cstdint>

#include "results/results.h"

namespace rayspec {

struct LeakCounts {
  uint64_t rays = 0, leaks = 0, doubles = 0;
  void add(const LeakCounts& o) {
    rays += o.rays;
    leaks += o.leaks;
    doubles += o.doubles;
  }
  // Per 1000 rays (0 without rays).
  double leakRate() const { return rays ? 1000.0 * leaks / rays : 0; }
  double doubleRate() const { return rays ? 1000.0 * doubles / rays : 0; }
};

// From the any_hit_runs of each ray's record.
LeakCounts countLeaks(const Results& r);

}  // namespace rayspec
