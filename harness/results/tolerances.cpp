#include "results/tolerances.h"

#include <algorithm>
#include <cmath>

#include "base/error_bounds.h"
#include "results/record_layout.h"

namespace rayspec {

bool Tolerance::matches(float device, float model) const {
  if (std::isnan(device) || std::isnan(model)) return std::isnan(device) && std::isnan(model);
  if (device == model) return true;  // also equal infinities
  return std::fabs(static_cast<double>(device) - model) <= allowance(model);
}

double Tolerance::allowance(float model) const {
  return abs + rel * std::max(std::fabs(static_cast<double>(model)), 1.0);
}

Tolerance toleranceOf(ToleranceKind t) {
  switch (t) {
    case ToleranceKind::Exact:
      return {0.0, 0.0};
    case ToleranceKind::Field:
      return {kFieldTolerance, kFieldTolerance};
    case ToleranceKind::Barycentric:
      return {kBarycentricTolerance, 0.0};
    case ToleranceKind::Color:
      return {kColorTolerance, kColorTolerance};
  }
  return {kFieldTolerance, kFieldTolerance};
}

// A name no row has (an image of no field): the field tolerance, as before
// the table.
Tolerance toleranceFor(std::string_view field) {
  const RecordField* f = findRecordField(field);
  return f ? toleranceOf(f->tolerance) : Tolerance{kFieldTolerance, kFieldTolerance};
}

}  // namespace rayspec
