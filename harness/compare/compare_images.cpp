#include <sstream>

#include "compare/compare_parts.h"
#include "compare/image_pair.h"

namespace rayspec {

// Each kept image against the model's, the pixels of numerically ambiguous
// rays (their legal answers differ by design) and of rays with undefined
// behaviour (R-UB: never judged) excluded; see image_pair.h. The
// case's thresholds per image: a tolerance scale and the failing pixels allowed.
void compareImages(const Plan& plan, const Results& device, const Results& model, const std::set<uint32_t>& masked,
                   Verdict& v) {
  for (const Image& di : device.images) {
    ImageOutput thresholds;
    for (const ImageOutput& out : plan.images)
      if (out.name == di.name) thresholds = out;
    const Image* mi = nullptr;
    for (const Image& candidate : model.images)
      if (candidate.name == di.name) mi = &candidate;
    if (!mi || mi->width != di.width || mi->height != di.height || mi->channels != di.channels ||
        mi->is_float != di.is_float || mi->texels.size() != di.texels.size()) {
      v.add({Status::Fail, "image", "image '" + di.name + "' missing or of another size in the model", {}, 1});
      continue;
    }
    const PixelCount count = countFailingPixels(prepareImagePair(di, *mi, masked, thresholds.tolerance));
    if (!count.failing) continue;
    std::ostringstream s;
    s << "image '" << di.name << "' differs from the model in " << count.failing << " pixels";
    if (di.is_float) s << " (largest difference " << count.max_error << "x the tolerance of '" << di.field << "')";
    if (thresholds.max_failing_pixels) s << ", " << thresholds.max_failing_pixels << " allowed";
    s << (count.by_oiio ? " [OpenImageIO compare]" : "");
    const Status status = count.failing > thresholds.max_failing_pixels ? Status::Fail : Status::Pass;
    v.add({status, "image", s.str(), count.first, static_cast<uint32_t>(count.failing)});
  }
}

}  // namespace rayspec
