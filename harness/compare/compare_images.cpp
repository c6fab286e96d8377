#include <sstream>

#include "compare/compare_parts.h"
#include "compare/image_pair.h"

namespace rayspec {

// Each kept image against the model's, the pixels of numerically ambiguous
// rays excluded (their legal answers differ by design); see image_pair.h.
void compareImages(const Results& device, const Results& model, const std::set<uint32_t>& ambiguous, Verdict& v) {
  for (const Image& di : device.images) {
    const Image* mi = nullptr;
    for (const Image& candidate : model.images)
      if (candidate.name == di.name) mi = &candidate;
    if (!mi || mi->width != di.width || mi->height != di.height || mi->channels != di.channels ||
        mi->is_float != di.is_float || mi->texels.size() != di.texels.size()) {
      v.add({Status::Fail, "image", "image '" + di.name + "' missing or of another size in the model", {}, 1});
      continue;
    }
    const PixelCount count = countFailingPixels(prepareImagePair(di, *mi, ambiguous));
    if (!count.failing) continue;
    std::ostringstream s;
    s << "image '" << di.name << "' differs from the model in " << count.failing << " pixels";
    if (di.is_float) s << " (largest difference " << count.max_error << "x the tolerance of '" << di.field << "')";
    s << (count.by_oiio ? " [OpenImageIO compare]" : "");
    v.add({Status::Fail, "image", s.str(), count.first, static_cast<uint32_t>(count.failing)});
  }
}

}  // namespace rayspec
