// Where another tier or a device disagrees with the model's exact tier, ray
// by ray, on one case (both results bundles of the same case and launch):
//   leak        the exact tier found the surface (closest-hit or any-hit
//               ran, or `hit` recorded 1), the other side found nothing, and
//               a miss is not legal there: a clear ray, or an ambiguous one
//               through a closed crossing (an edge shared by two triangles,
//               a vertex closed by a fan: compare/shared_edge.h) or one
//               whose legal answers hold no miss and that does not only
//               cross the outer border of a mesh
//   double hit  the exact tier ran any-hit exactly once on the ray, the
//               other side more than once (a primitive edge crossed twice;
//               where several non-opaque layers lie along a ray a device
//               that visits them far to near legally runs more, see
//               bench/README.md)
//   other primitive  both hit, and the primitive, geometry or instance
//               (those both recorded) differs, not one of the legal answers
//   extra hit   the exact tier found nothing on a clear ray, the other side
//               a surface
// and the hit distance error in ULPs where both hit the same primitive and
// recorded hit_t. Rays whose behaviour is undefined (R-UB) are left out.
#pragma once

#include <cstdint>

#include "accuracy/t_errors.h"
#include "case/case.h"
#include "results/results.h"

namespace rayspec {

struct Disagreements {
  uint64_t rays = 0;         // rays compared (R-UB rays left out)
  uint64_t disagreeing = 0;  // rays with at least one of the four below
  uint64_t leaks = 0, double_hits = 0, other_primitive = 0, extra_hits = 0;
  TErrors t;
  void add(const Disagreements& o);
  // Disagreeing rays per million rays compared (0 without rays).
  double perMillion() const { return rays ? 1e6 * static_cast<double>(disagreeing) / rays : 0; }
};

// `c` (the case, for its triangles) may be null: then an ambiguous ray on
// which a miss is legal counts as a leak only when the exact tier listed two
// or more triangles sharing the crossing (RayAmbiguity::shared_triangles).
// Bundles of different launches compare nothing (rays 0).
Disagreements countDisagreements(const Results& exact, const Results& other, const Case* c);

}  // namespace rayspec
