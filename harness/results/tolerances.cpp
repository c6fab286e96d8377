#include "results/tolerances.h"

#include <algorithm>
#include <cmath>

#include "base/error_bounds.h"

namespace rayspec {

bool Tolerance::matches(float device, float model) const {
  if (std::isnan(device) || std::isnan(model)) return std::isnan(device) && std::isnan(model);
  if (device == model) return true;  // also equal infinities
  const double diff = std::fabs(static_cast<double>(device) - model);
  return diff <= abs + rel * std::max(std::fabs(static_cast<double>(model)), 1.0);
}

Tolerance toleranceFor(std::string_view field) {
  if (field == "barycentrics") return {kBarycentricTolerance, 0.0};
  if (field == "color" || field == "color2") return {kColorTolerance, kColorTolerance};
  return {kFieldTolerance, kFieldTolerance};
}

}  // namespace rayspec
