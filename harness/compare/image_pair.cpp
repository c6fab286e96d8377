#include "compare/image_pair.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "compare/compare_results.h"
#include "results/tolerances.h"

namespace rayspec {

ImagePair prepareImagePair(const Image& d, const Image& m, const std::set<uint32_t>& excluded,
                           double scale) {
  ImagePair p;
  p.width = d.width;
  p.height = d.height;
  p.channels = d.channels;
  p.difference.assign(d.texels.size(), 0.0f);
  const Tolerance tol = toleranceFor(d.field);
  const size_t pixels = static_cast<size_t>(d.width) * d.height;
  for (size_t px = 0; px < pixels; ++px) {
    if (excluded.count(static_cast<uint32_t>(px))) continue;
    for (uint32_t ch = 0; ch < d.channels; ++ch) {
      const size_t i = px * d.channels + ch;
      const uint32_t a = d.texels[i], b = m.texels[i];
      if (a == b) continue;
      if (!d.is_float) {
        p.difference[i] = 2.0f;
        continue;
      }
      const float fa = std::bit_cast<float>(a), fb = std::bit_cast<float>(b);
      if (std::isnan(fa) || std::isnan(fb)) {
        p.difference[i] = std::isnan(fa) && std::isnan(fb) ? 0.0f : 1e30f;
        continue;
      }
      if (fa == fb) continue;
      const double allowance =
          (tol.abs + tol.rel * std::max(std::fabs(static_cast<double>(fb)), 1.0)) * scale;
      const double diff = std::fabs(static_cast<double>(fa) - fb);
      p.difference[i] = static_cast<float>(std::min(diff / allowance, 1e30));
    }
  }
  return p;
}

PixelCount countFailingPixelsLoop(const ImagePair& p) {
  PixelCount c;
  const size_t pixels = static_cast<size_t>(p.width) * p.height;
  for (size_t px = 0; px < pixels; ++px) {
    double worst = 0.0;
    for (uint32_t ch = 0; ch < p.channels; ++ch)
      worst = std::max(worst, static_cast<double>(p.difference[px * p.channels + ch]));
    c.max_error = std::max(c.max_error, worst);
    if (worst <= 1.0) continue;
    ++c.failing;
    if (c.first.size() < kFirstRays) c.first.push_back(static_cast<uint32_t>(px));
  }
  return c;
}

}  // namespace rayspec
