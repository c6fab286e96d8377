#include <cstring>

#include "compare/compare_parts.h"
#include "compare/tolerances.h"

namespace rayspec {

// Texel by texel, skipping the pixels of numerically ambiguous rays (their
// legal answers differ by design). Uint images exactly, float images within
// the tolerance of the field they show.
void compareImages(const Results& device, const Results& model, const std::set<uint32_t>& ambiguous, Verdict& v) {
  for (const Image& di : device.images) {
    const Image* mi = nullptr;
    for (const Image& candidate : model.images)
      if (candidate.name == di.name) mi = &candidate;
    FindingBuilder b;
    b.finding = {Status::Fail, "image", "image '" + di.name + "' differs from the model"};
    if (!mi || mi->width != di.width || mi->height != di.height || mi->channels != di.channels ||
        mi->texels.size() != di.texels.size()) {
      b.finding.message = "image '" + di.name + "' missing or of another size in the model";
      b.finding.ray_count = 1;
      b.flush(v);
      continue;
    }
    const Tolerance tol = toleranceFor(di.field);
    const size_t pixels = static_cast<size_t>(di.width) * di.height;
    for (size_t p = 0; p < pixels; ++p) {
      if (ambiguous.count(static_cast<uint32_t>(p))) continue;
      bool same = true;
      for (uint32_t ch = 0; ch < di.channels && same; ++ch) {
        const uint32_t a = di.texels[p * di.channels + ch], m = mi->texels[p * di.channels + ch];
        if (di.is_float) {
          float fa, fm;
          std::memcpy(&fa, &a, 4);
          std::memcpy(&fm, &m, 4);
          same = tol.matches(fa, fm);
        } else {
          same = a == m;
        }
      }
      if (!same) b.addRay(static_cast<uint32_t>(p));
    }
    if (b.finding.ray_count) b.finding.message += " in " + std::to_string(b.finding.ray_count) + " pixels";
    b.flush(v);
  }
}

}  // namespace rayspec
