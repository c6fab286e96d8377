// Two images of one execution that the case declares equal (`equal_to`).
#include "compare/compare_parts.h"

namespace rayspec {
namespace {

const Image* findImage(const Results& r, const std::string& name) {
  for (const Image& im : r.images)
    if (im.name == name) return &im;
  return nullptr;
}

// Pixels whose texels differ (all of them when the shapes differ), and the
// first few pixel indices.
uint32_t differingPixels(const Image& a, const Image& b, std::vector<uint32_t>* first) {
  const size_t pixels = static_cast<size_t>(a.width) * a.height;
  if (a.width != b.width || a.height != b.height || a.channels != b.channels ||
      a.texels.size() != b.texels.size())
    return static_cast<uint32_t>(pixels);
  uint32_t n = 0;
  for (size_t p = 0; p < pixels; ++p) {
    bool same = true;
    for (uint32_t k = 0; k < a.channels; ++k)
      same = same && a.texels[p * a.channels + k] == b.texels[p * b.channels + k];
    if (same) continue;
    if (first->size() < kFirstRays) first->push_back(static_cast<uint32_t>(p));
    ++n;
  }
  return n;
}

}  // namespace

void compareEqualImages(const Plan& plan, const Results& device, const Results& model, Verdict& v) {
  for (const ImageOutput& out : plan.images) {
    if (out.equal_to.empty()) continue;
    // The model first: where its own images differ, the case is at fault and
    // the device is not judged on the pair.
    for (const auto& [side, r, status] : {std::tuple{"model", &model, Status::CaseError},
                                          std::tuple{"device", &device, Status::Fail}}) {
      const Image* a = findImage(*r, out.name);
      const Image* b = findImage(*r, out.equal_to);
      const std::string pair = "images '" + out.name + "' and '" + out.equal_to + "'";
      Finding f{status, "image", "", {}, 0};
      if (!a || !b) {
        f.message = pair + ": missing on the " + side;
        f.ray_count = 1;
        v.add(f);
        break;
      }
      f.ray_count = differingPixels(*a, *b, &f.rays);
      f.message = pair + (f.ray_count ? " differ on the " + std::string(side) + " in " +
                                            std::to_string(f.ray_count) +
                                            " pixels (equal_to: texel for texel)"
                                      : " are equal on the " + std::string(side));
      if (!f.ray_count) f.status = Status::Pass;
      v.add(f);
      if (f.status == Status::CaseError) break;
    }
  }
}

}  // namespace rayspec
