// Documented tolerances for float fields (R-PREC: the specification promises
// no numeric bound, so the suite states its own). A device value d matches the
// model value m when |d - m| <= abs + rel * max(|m|, 1). Each field's is the
// tolerance column of results/record_field_table.h.
//   hit_t, ray_tmin, ray_tmax       abs 1e-5, rel 1e-5
//   barycentrics                    abs 1e-4 (float32 edge functions on a
//                                   unit-size triangle)
//   positions and directions        abs 1e-5, rel 1e-5
//   color                           abs 1e-4, rel 1e-4 (lights divide by d^2)
// The numbers are named, with where each comes from, in base/error_bounds.h.
#pragma once

#include <string>
#include <string_view>

namespace rayspec {

struct Tolerance {
  double abs = 0.0, rel = 0.0;
  bool matches(float device, float model) const;
  // How far a device value may lie from a finite model value: abs + rel * max(|model|, 1).
  double allowance(float model) const;
};

enum class ToleranceKind;
Tolerance toleranceOf(ToleranceKind t);
Tolerance toleranceFor(std::string_view field);  // the field's row's, by name

}  // namespace rayspec
