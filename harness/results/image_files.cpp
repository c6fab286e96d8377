#include "results/image_files.h"

#include "results/results_io.h"

#ifdef RAYSPEC_WITH_OIIO
#include <OpenImageIO/imageio.h>
#endif

namespace rayspec {

#ifdef RAYSPEC_WITH_OIIO
namespace {

std::string writeOne(const std::string& path, const OIIO::ImageSpec& spec, const void* pixels) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return "OpenImageIO cannot create " + path + ": " + OIIO::geterror();
  if (!out->open(path, spec) || !out->write_image(spec.format, pixels)) return path + ": " + out->geterror();
  out->close();
  return {};
}

}  // namespace

std::string writeImageFiles(const Image& im, const std::string& dir) {
  const std::vector<uint8_t> preview = previewPixels(im);
  OIIO::ImageSpec png(static_cast<int>(im.width), static_cast<int>(im.height), 4, OIIO::TypeDesc::UINT8);
  std::string err = writeOne(dir + "/" + im.name + ".png", png, preview.data());
  if (!err.empty() || !im.is_float) return err;
  OIIO::ImageSpec exr(static_cast<int>(im.width), static_cast<int>(im.height), static_cast<int>(im.channels),
                      OIIO::TypeDesc::FLOAT);
  return writeOne(dir + "/" + im.name + ".exr", exr, im.texels.data());
}

bool imageFilesSupported() { return true; }

#else

std::string writeImageFiles(const Image&, const std::string&) { return {}; }
bool imageFilesSupported() { return false; }

#endif

}  // namespace rayspec
