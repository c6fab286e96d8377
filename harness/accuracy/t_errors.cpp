#include "accuracy/t_errors.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rayspec {

double ulpError(float t, float t_exact) {
  if (!std::isfinite(t) || !std::isfinite(t_exact)) return std::numeric_limits<double>::quiet_NaN();
  const float a = std::fabs(t_exact);
  const double ulp =
      static_cast<double>(std::nextafter(a, std::numeric_limits<float>::infinity())) - a;
  return std::fabs(static_cast<double>(t) - static_cast<double>(t_exact)) / ulp;
}

size_t tErrorBin(double ulps) {
  if (ulps <= 0) return 0;
  if (ulps <= 1) return 1;
  const int e = static_cast<int>(std::ceil(std::log2(ulps)));  // ulps in (2^(e-1), 2^e]
  return std::min<size_t>(static_cast<size_t>(e) + 1, kTErrorBins - 1);
}

std::string tErrorBinLabel(size_t bin) {
  if (bin == 0) return "0";
  if (bin + 1 >= kTErrorBins) return ">" + std::to_string(1ull << (kTErrorBins - 3));
  return std::to_string(1ull << (bin - 1));
}

void TErrors::add(double ulps) {
  if (std::isnan(ulps)) return;
  ulps_.push_back(ulps);
  ++histogram_[tErrorBin(ulps)];
}

void TErrors::add(const TErrors& other) {
  ulps_.insert(ulps_.end(), other.ulps_.begin(), other.ulps_.end());
  for (size_t i = 0; i < kTErrorBins; ++i) histogram_[i] += other.histogram_[i];
}

double TErrors::quantile(double q) const {
  if (ulps_.empty()) return 0;
  std::vector<double> v = ulps_;
  const size_t rank = static_cast<size_t>(std::ceil(std::clamp(q, 0.0, 1.0) * v.size()));
  const size_t k = rank == 0 ? 0 : rank - 1;
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

double TErrors::max() const {
  return ulps_.empty() ? 0 : *std::max_element(ulps_.begin(), ulps_.end());
}

}  // namespace rayspec
