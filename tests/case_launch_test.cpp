// rays.launch (R-LAUNCH-3D): the launch size a case gives, its rays in launch
// order, a zero dimension keeping no rays, and each error at its line and
// field.
#include <gtest/gtest.h>

#include "case/parse_case.h"
#include "case_support.h"

namespace rayspec {
namespace {

ParseResult parseWith(const std::string& launch, const std::string& outputs = "") {
  return parseCaseText(
      "rules: [R-LAUNCH-3D]\n"
      "rays:\n"
      "  grid: {size: [4, 6], origin: [0, 0, 1], du: [1, 0, 0], dv: [0, 1, 0], "
      "direction: [0, 0, -1]}\n"
      "  launch: " +
          launch +
          "\n"
          "pipeline:\n"
          "  raygen: [count: raygen, record: {value: launch_id_z}]\n"
          "outputs:\n"
          "  counters: [raygen]\n"
          "  per_ray: [value]\n" +
          outputs,
      "t.yaml", "t/t");
}

TEST(Launch, ThreeDimensionsShapeTheRecordsAsLayers) {
  const ParseResult r = parseWith("[4, 3, 2]");
  ASSERT_TRUE(r.value) << firstError(r);
  EXPECT_EQ(r.value->rays.launchSize(), (std::array<uint32_t, 3>{4, 3, 2}));
  EXPECT_EQ(r.value->rays.width, 4u);
  EXPECT_EQ(r.value->rays.height, 6u);
  EXPECT_EQ(r.value->rays.rays.size(), 24u);
}

TEST(Launch, WithoutTheFieldTheLaunchIsTheFormsSize) {
  const ParseResult r = parseCaseText(
      "rules: [R-MASK]\nrays:\n  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}, "
      "{origin: [0, 0, 1], direction: [0, 0, -1]}]\noutputs:\n  per_ray: [hit]\n",
      "t.yaml", "t/t");
  ASSERT_TRUE(r.value) << firstError(r);
  EXPECT_EQ(r.value->rays.launchSize(), (std::array<uint32_t, 3>{2, 1, 1}));
}

TEST(Launch, AZeroDimensionKeepsNoRays) {
  for (const std::string launch : {"[0, 6, 1]", "[4, 0, 2]", "[4, 6, 0]"}) {
    const ParseResult r = parseWith(launch);
    ASSERT_TRUE(r.value) << launch << ": " << firstError(r);
    EXPECT_TRUE(r.value->rays.rays.empty()) << launch;
    EXPECT_EQ(uint64_t(r.value->rays.width) * r.value->rays.height, 0u) << launch;
  }
}

TEST(Launch, ErrorsNameTheLineAndField) {
  struct Bad {
    std::string launch, message;
  } bad[] = {{"[4, 3, 3]", "4 x 3 x 3 = 36 rays, but the rays give 24"},
             {"[4, 6]", "expected [width, height, depth]"},
             {"[4, -1, 6]", "rays.launch[1]"}};
  for (const Bad& b : bad) {
    const ParseResult r = parseWith(b.launch);
    EXPECT_FALSE(r.value) << b.launch;
    const std::string e = firstError(r);
    EXPECT_NE(e.find("t.yaml:4"), std::string::npos) << e;
    EXPECT_NE(e.find("rays.launch"), std::string::npos) << e;
    EXPECT_NE(e.find(b.message), std::string::npos) << e;
  }
}

TEST(Launch, AZeroLaunchCannotHaveImages) {
  const ParseResult r = parseWith("[4, 0, 2]", "  images: [{name: v, from: value}]\n");
  EXPECT_FALSE(r.value);
  EXPECT_NE(firstError(r).find("has no texels"), std::string::npos) << firstError(r);
}

}  // namespace
}  // namespace rayspec
