// Hit distance errors in units of float ULP: |t - t_exact| divided by the
// spacing of floats at t_exact, their median, 99th percentile, maximum and a
// histogram by powers of two.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace rayspec {

// |t - t_exact| in ULPs of t_exact (the gap between |t_exact| and the next
// float up; the smallest subnormal at 0). NaN when either is not finite.
double ulpError(float t, float t_exact);

// Histogram bins: [0] exactly 0 ULP; [1] (0, 1]; [k] (2^(k-2), 2^(k-1)] for
// k = 2 .. kTErrorBins - 2; the last one everything beyond 2^(kTErrorBins-3).
inline constexpr size_t kTErrorBins = 18;
size_t tErrorBin(double ulps);
// The bin's upper bound as text: "0", "1", "2", "4", ..., "32768", ">32768".
std::string tErrorBinLabel(size_t bin);

class TErrors {
 public:
  void add(double ulps);  // NaN is left out
  void add(const TErrors& other);
  size_t count() const { return ulps_.size(); }
  // Nearest rank (the smallest error with at least q of the errors at or
  // below it); 0 without errors.
  double quantile(double q) const;
  double median() const { return quantile(0.5); }
  double p99() const { return quantile(0.99); }
  double max() const;
  const std::array<uint64_t, kTErrorBins>& histogram() const { return histogram_; }

 private:
  std::vector<double> ulps_;
  std::array<uint64_t, kTErrorBins> histogram_{};
};

}  // namespace rayspec
