#include "bundle/image_files.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>

#include "bundle/results_io.h"

#ifdef RAYSPEC_WITH_OIIO
#include <OpenImageIO/imageio.h>
#endif

namespace rayspec {

#ifdef RAYSPEC_WITH_OIIO
namespace {

// The image file at `path`; the error (ErrorKind::Harness) names it and says
// what OpenImageIO said.
Result<void> writeOne(const std::string& path, OIIO::ImageSpec spec, const void* pixels) {
  // Without a DateTime, the EXR writer stamps the current time (capDate):
  // two runs would write different files for the same image.
  spec.attribute("DateTime", "");
  auto out = OIIO::ImageOutput::create(path);
  if (!out)
    return errorOf(ErrorKind::Harness,
                   "OpenImageIO cannot create " + path + ": " + OIIO::geterror());
  if (!out->open(path, spec) || !out->write_image(spec.format, pixels))
    return errorOf(ErrorKind::Harness, path + ": " + out->geterror());
  out->close();
  return {};
}

}  // namespace

Result<void> writeImageFiles(const Image& im, const std::string& dir) {
  const std::vector<uint8_t> preview = previewPixels(im);
  OIIO::ImageSpec png(static_cast<int>(im.width), static_cast<int>(im.height), 4,
                      OIIO::TypeDesc::UINT8);
  RAYSPEC_TRY_VOID(writeOne(dir + "/" + im.name + ".png", png, preview.data()));
  if (!im.is_float) return {};
  OIIO::ImageSpec exr(static_cast<int>(im.width), static_cast<int>(im.height),
                      static_cast<int>(im.channels), OIIO::TypeDesc::FLOAT);
  return writeOne(dir + "/" + im.name + ".exr", exr, im.texels.data());
}

Result<void> writeDiffImage(const Image& a, const Image& b, const std::string& dir) {
  if (a.texels.size() != b.texels.size() || a.width != b.width || a.height != b.height) return {};
  std::vector<uint8_t> px(static_cast<size_t>(a.width) * a.height * 4, 0);
  for (size_t p = 0; p < static_cast<size_t>(a.width) * a.height; ++p) {
    double diff = 0.0;
    for (uint32_t c = 0; c < a.channels; ++c) {
      const uint32_t wa = a.texels[p * a.channels + c], wb = b.texels[p * a.channels + c];
      if (wa == wb) continue;
      if (a.is_float) {
        const float fa = std::bit_cast<float>(wa), fb = std::bit_cast<float>(wb);
        diff = std::max(diff, std::fabs(static_cast<double>(fa) - fb));
      } else {
        diff = 1.0;
      }
    }
    uint8_t* out = &px[p * 4];
    if (diff > 0) {
      out[0] = static_cast<uint8_t>(128 + 127 * std::min(diff * 10.0, 1.0));
    } else {
      out[0] = out[1] = out[2] = 40;
    }
    out[3] = 255;
  }
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  OIIO::ImageSpec png(static_cast<int>(a.width), static_cast<int>(a.height), 4,
                      OIIO::TypeDesc::UINT8);
  return writeOne(dir + "/" + a.name + ".png", png, px.data());
}

bool imageFilesSupported() {
  return true;
}

#else

Result<void> writeImageFiles(const Image&, const std::string&) {
  return {};
}
Result<void> writeDiffImage(const Image&, const Image&, const std::string&) {
  return {};
}
bool imageFilesSupported() {
  return false;
}

#endif

}  // namespace rayspec
