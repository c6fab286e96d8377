// Images a case declares equal (`equal_to`): compared texel for texel on
// each side; a difference on the device fails, in the model it is the
// case's error.
#include <gtest/gtest.h>

#include "compare/compare_results.h"

namespace rayspec {
namespace {

Image image(const std::string& name, std::vector<uint32_t> texels) {
  Image im;
  im.name = name;
  im.field = "color";
  im.width = 2;
  im.height = 1;
  im.channels = 4;
  im.is_float = true;
  im.texels.assign(texels.begin(), texels.end());
  return im;
}

struct Pair {
  Case c;
  Plan plan;
  Results device, model;
};

// Two 2x1 rgba32f images a and b, b declared equal to a, equal on both sides.
Pair equalPair() {
  Pair p;
  ImageOutput a{"a", "color"}, b{"b", "color2"};
  b.equal_to = "a";
  p.plan.images = {a, b};
  const std::vector<uint32_t> texels = {1, 2, 3, 4, 5, 6, 7, 8};
  for (Results* r : {&p.device, &p.model}) {
    r->width = 2;
    r->height = 1;
    r->images = {image("a", texels), image("b", texels)};
  }
  return p;
}

bool hasFinding(const Verdict& v, Status s, const std::string& text) {
  for (const Finding& f : v.findings)
    if (f.status == s && f.message.find(text) != std::string::npos) return true;
  return false;
}

TEST(EqualImages, EqualOnBothSidesPasses) {
  const Pair p = equalPair();
  const Verdict v = compareResults(p.c, p.plan, p.device, p.model);
  EXPECT_EQ(v.status, Status::Pass) << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::Pass, "are equal on the device"));
}

TEST(EqualImages, ADifferenceOnTheDeviceFails) {
  Pair p = equalPair();
  p.device.images[1].texels[5] ^= 1;  // pixel 1, green: one bit
  const Verdict v = compareResults(p.c, p.plan, p.device, p.model);
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::Fail, "differ on the device in 1 pixels")) << v.headline();
  for (const Finding& f : v.findings) {
    if (f.status == Status::Fail && f.message.find("differ on the device") != std::string::npos) {
      EXPECT_EQ(f.rays, std::vector<uint32_t>{1});
    }
  }
}

TEST(EqualImages, ADifferenceInTheModelIsTheCasesError) {
  Pair p = equalPair();
  p.model.images[1].texels[0] ^= 1;
  p.device.images = p.model.images;  // the device agrees with the model
  const Verdict v = compareResults(p.c, p.plan, p.device, p.model);
  EXPECT_EQ(v.status, Status::CaseError) << "the device is not blamed: " << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::CaseError, "differ on the model in 1 pixels")) << v.headline();
}

TEST(EqualImages, AMissingImageIsNamed) {
  Pair p = equalPair();
  p.device.images.pop_back();
  const Verdict v = compareResults(p.c, p.plan, p.device, p.model);
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_TRUE(hasFinding(v, Status::Fail, "missing on the device")) << v.headline();
}

}  // namespace
}  // namespace rayspec
