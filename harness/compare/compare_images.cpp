#include <algorithm>
#include <sstream>

#include "compare/compare_parts.h"
#include "compare/image_pair.h"

namespace rayspec {

// Each kept image against the model's, the pixels of numerically ambiguous
// rays (their legal answers differ by design) and of rays with undefined
// behaviour (R-UB: never judged) excluded; see image_pair.h. The
// case's thresholds per image: a tolerance scale and the failing pixels allowed.
void compareImages(const Plan& plan, const Results& device, const Results& model,
                   const std::set<uint32_t>& masked, Verdict& v) {
  for (const Image& di : device.images) {
    ImageOutput thresholds;
    for (const ImageOutput& out : plan.images)
      if (out.name == di.name) thresholds = out;
    const Image* mi = nullptr;
    for (const Image& candidate : model.images)
      if (candidate.name == di.name) mi = &candidate;
    if (!mi || mi->width != di.width || mi->height != di.height || mi->channels != di.channels ||
        mi->is_float != di.is_float || mi->texels.size() != di.texels.size()) {
      v.add({Status::Fail,
             "image",
             "image '" + di.name + "' missing or of another size in the model",
             {},
             1});
      continue;
    }
    // R-AHIT-DUP: the pixels of rays whose field a repeated any-hit may change.
    std::set<uint32_t> image_masked = masked;
    const int field = recordFieldIndex(di.field);
    for (const RepeatDependentRay& d : model.repeat_dependent)
      if (field >= 0 && (d.fields & fieldBit(field))) image_masked.insert(d.ray);
    const PixelCount count =
        countFailingPixels(prepareImagePair(di, *mi, image_masked, thresholds.tolerance));
    if (!count.failing) continue;
    std::ostringstream s;
    s << "image '" << di.name << "' differs from the model in " << count.failing << " pixels";
    if (di.is_float)
      s << " (largest difference " << count.max_error << "x the tolerance of '" << di.field << "')";
    if (thresholds.max_failing_pixels) s << ", " << thresholds.max_failing_pixels << " allowed";
    s << (count.by_oiio ? " [OpenImageIO compare]" : "");
    const Status status =
        count.failing > thresholds.max_failing_pixels ? Status::Fail : Status::Pass;
    v.add({status, "image", s.str(), count.first, static_cast<uint32_t>(count.failing)});
  }
}

void compareImagesToRecords(const Results& device, const std::set<uint32_t>& rays, Verdict& v) {
  const uint32_t words = recordWords();
  for (const Image& im : device.images) {
    const RecordField* f = findRecordField(im.field);
    if (!f) continue;
    const int index = recordFieldIndex(im.field);
    const uint32_t shown = std::min(f->words, im.channels);
    FindingBuilder b;
    b.finding = {Status::Fail, "image",
                 "image '" + im.name + "' shows other values than the device's own records of '" +
                     im.field + "' on numerically ambiguous rays"};
    for (uint32_t ray : rays) {
      if (static_cast<size_t>(ray) >= static_cast<size_t>(im.width) * im.height ||
          static_cast<size_t>(ray + 1) * words > device.records.size())
        continue;
      const uint32_t* rec = &device.records[static_cast<size_t>(ray) * words];
      if (!f->automatic && !written(rec, index)) continue;
      for (uint32_t k = 0; k < shown; ++k)
        if (im.texels[static_cast<size_t>(ray) * im.channels + k] != rec[f->offset + k]) {
          b.addRay(ray);
          break;
        }
    }
    b.flush(v);
  }
}

}  // namespace rayspec
