// Axis ranges and tick values for line plots.
#include <cmath>

#include "plot/line_plot.h"

namespace rayspec {

AxisTicks axisTicks(double min, double max, bool log) {
  AxisTicks a;
  if (!(min <= max)) min = max = log ? 1 : 0;
  if (log) {
    const int lo = static_cast<int>(std::floor(std::log10(min) + 1e-9));
    int hi = static_cast<int>(std::ceil(std::log10(max) - 1e-9));
    if (hi <= lo) hi = lo + 1;
    a.lo = std::pow(10.0, lo);
    a.hi = std::pow(10.0, hi);
    for (int k = lo; k <= hi; ++k) a.ticks.push_back(std::pow(10.0, k));
    return a;
  }
  if (min == max) {
    max = min + (min == 0 ? 1 : std::fabs(min));
    if (min > 0) min = 0;
  }
  const double raw = (max - min) / 5;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  double step = p;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) {
      step = m * p;
      break;
    }
  a.lo = std::floor(min / step) * step;
  a.hi = std::ceil(max / step) * step;
  for (double t = a.lo; t <= a.hi + step / 2; t += step)
    a.ticks.push_back(std::fabs(t) < step * 1e-9 ? 0 : t);
  return a;
}

}  // namespace rayspec
