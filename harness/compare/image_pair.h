// A device image and the model's, prepared once for counting failing pixels
// (internal to compare/). The masking and the tolerance live here only:
//   - pixels of numerically ambiguous rays, and of rays with undefined
//     behaviour (R-UB), are excluded (difference 0);
//   - Uint images: 1 where the texels differ, else 0 (ids compare exactly);
//   - Float images: (device - model) / allowance per channel, the allowance
//     being the field's tolerance (abs + rel * max(|model|, 1)) times the
//     image's threshold scale; NaN against NaN is equal, NaN against a number
//     differs.
// A pixel fails when some channel's prepared difference exceeds 1. The count
// is taken by OpenImageIO's ImageBufAlgo::compare when built with it, else by
// a texel loop over the same prepared planes.
#pragma once

#include <cstdint>
#include <set>
#include <vector>

#include "results/results.h"

namespace rayspec {

struct ImagePair {
  uint32_t width = 0, height = 0, channels = 1;
  std::vector<float> difference;  // prepared device plane (the reference plane is all zero)
};

ImagePair prepareImagePair(const Image& device, const Image& model,
                           const std::set<uint32_t>& excluded, double threshold_scale = 1.0);

struct PixelCount {
  size_t failing = 0;
  double max_error = 0.0;       // in allowances (1 = exactly at the tolerance)
  bool by_oiio = false;         // counted by OpenImageIO
  std::vector<uint32_t> first;  // first failing pixels (launch index), at most kFirstRays
};

PixelCount countFailingPixels(const ImagePair& p);      // OpenImageIO when available
PixelCount countFailingPixelsLoop(const ImagePair& p);  // always the texel loop

}  // namespace rayspec
