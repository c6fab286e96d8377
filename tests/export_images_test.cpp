// rayspec export of images (outputs.images, export/export_c.h): the storage
// images the stages write, read back and compared with the model's texels as
// the judge compares them (compare/image_pair.h): ids exactly, floats within
// the field's tolerance times the image's scale, the pixels of ambiguous and
// undefined rays left out. Texels planted wrong in the expectations make the
// export fail; one moved within the tolerance does not.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>

#include "export_play.h"
#include "results/tolerances.h"

namespace rayspec {
namespace {

Image& plantedImage(Results& r, const std::string& name) {
  for (Image& im : r.images)
    if (im.name == name) return im;
  ADD_FAILURE() << "no image " << name;
  return r.images.at(0);
}

// The first pixel of `im` whose ray is neither ambiguous nor undefined and
// whose first texel is a number other than 0.
size_t judgedPixel(const Results& model, const Image& im) {
  const size_t pixels = size_t(im.width) * im.height;
  for (size_t px = 0; px < pixels; ++px) {
    const uint32_t t = im.texels[px * im.channels];
    const bool number = !im.is_float || std::isfinite(std::bit_cast<float>(t));
    const auto ray_is = [px](const auto& list) {
      return std::any_of(list.begin(), list.end(), [px](const auto& a) { return a.ray == px; });
    };
    if (t != 0 && number && !ray_is(model.ambiguous) && !ray_is(model.undefined)) return px;
  }
  ADD_FAILURE() << "no judged pixel in image " << im.name;
  return 0;
}

TEST(ExportImages, CasesWithImagesPassOnLavapipe) {
  // An id image (r32ui) and a float one (rgba32f).
  for (const char* name : {"results/miss-xor-closest-hit", "callable/lights"}) {
    const ExportCase l = loadExportCase(name);
    const Played p = exportAndPlay(l, exportModelOf(l), l.c.name);
    EXPECT_EQ(p.status, 0) << name << ":\n" << p.output;
    EXPECT_NE(p.output.find("PASS: "), std::string::npos) << p.output;
  }
}

TEST(ExportImages, AnIdTexelPlantedWrongFails) {
  const ExportCase l = loadExportCase("results/miss-xor-closest-hit");
  Results model = exportModelOf(l);
  Image& im = plantedImage(model, "hit");
  const size_t px = judgedPixel(model, im);
  im.texels[px] ^= 1u;
  const Played p = exportAndPlay(l, model, "image-id-flipped");
  EXPECT_EQ(p.status, 1) << p.output;
  EXPECT_NE(p.output.find("FAIL: image: image 'hit' differs from the model in 1 pixels (0 "
                          "allowed); first: pixel " +
                          std::to_string(px)),
            std::string::npos)
      << p.output;
}

TEST(ExportImages, AFloatTexelIsHeldWithinTheFieldsTolerance) {
  // A texel of the color image moved by half its allowance passes; by twice
  // its allowance fails.
  const ExportCase l = loadExportCase("callable/lights");
  const Results model = exportModelOf(l);
  const Tolerance tol = toleranceFor("color");
  for (const double by : {0.5, 2.0}) {
    Results moved = model;
    Image& im = plantedImage(moved, "color");
    const size_t px = judgedPixel(moved, im);
    const float v = std::bit_cast<float>(im.texels[px * im.channels]);
    const double allowance = tol.abs + tol.rel * std::max(std::fabs(double(v)), 1.0);
    im.texels[px * im.channels] = std::bit_cast<uint32_t>(float(v + by * allowance));
    const Played p = exportAndPlay(l, moved, "image-float-moved-" + std::to_string(by));
    EXPECT_EQ(p.status, by < 1 ? 0 : 1) << by << ":\n" << p.output;
    if (by > 1) {
      EXPECT_NE(p.output.find("FAIL: image: image 'color' differs from the model in 1 pixels"),
                std::string::npos)
          << p.output;
    }
  }
}

}  // namespace
}  // namespace rayspec
