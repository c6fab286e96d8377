#include "model/box_bound.h"

#include <algorithm>
#include <cmath>

#include "base/error_bounds.h"

namespace rayspec {

DVec3 boxFaceBounds(const DVec3& lo, const DVec3& hi, const WatertightRay& w) {
  DVec3 bound;
  double reach = 0, dm = 0, most = 0;
  const double origin = largestMagnitude(w.o);
  for (int k = 0; k < 3; ++k) {
    bound[k] = kDeviceRelTolerance *
                   std::max({std::fabs(lo[k]), std::fabs(hi[k]), origin, kMagnitudeFloor}) +
               boxSlack(lo[k], hi[k]) + w.origin_err[k];
    reach = std::max({reach, std::fabs(lo[k] - w.o[k]), std::fabs(hi[k] - w.o[k])});
    dm = std::max(dm, std::fabs(w.d[k]));
    most = std::max(most, bound[k]);
  }
  if (!(dm > 0)) return bound;
  const double t_reach = (reach + most) / dm;
  for (int k = 0; k < 3; ++k) bound[k] += t_reach * w.direction_err[k];
  return bound;
}

}  // namespace rayspec
