// rays.launch (R-LAUNCH-3D): the launch size a case gives, its rays in launch
// order, a zero dimension keeping no rays, rays.same (one ray for every id of
// a launch too wide to list), and each error at its line and field.
#include <gtest/gtest.h>

#include "parse/parse_case.h"
#include "parse_support.h"

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

// rays.same: a launch of any size up to 2^30 ids, every id the one ray.
ParseResult parseSame(const std::string& same, const std::string& launch,
                      const std::string& raygen = "[count: raygen]") {
  return parseCaseText(
      "rules: [R-LAUNCH-3D]\n"
      "rays:\n"
      "  same: " +
          same + "\n" + (launch.empty() ? std::string() : "  launch: " + launch + "\n") +
          "  tmax: 7\n"
          "pipeline:\n"
          "  raygen: " +
          raygen +
          "\n"
          "outputs:\n"
          "  counters: [raygen]\n",
      "t.yaml", "t/t");
}

TEST(Launch, TheSameRayForEveryIdKeepsOneRay) {
  const ParseResult r =
      parseSame("{origin: [0, 0, 1], direction: [0, 0, -1], cull_mask: 3}", "[70000, 3, 2]");
  ASSERT_TRUE(r.value) << firstError(r);
  const Rays& rays = r.value->rays;
  EXPECT_TRUE(rays.same);
  ASSERT_EQ(rays.rays.size(), 1u);
  EXPECT_EQ(rays.launchRays(), 420000u);
  EXPECT_EQ(rays.width, 70000u);
  EXPECT_EQ(rays.height, 6u);
  // The defaults under the ray's own fields, for every id alike.
  EXPECT_EQ(rays.launchRay(419999).cull_mask, 3u);
  EXPECT_EQ(rays.launchRay(12345).tmax, 7.0f);
  EXPECT_EQ(&rays.launchRay(0), &rays.launchRay(419999));
}

TEST(Launch, TheSameRayWithAZeroDimensionKeepsNoRays) {
  const ParseResult r = parseSame("{origin: [0, 0, 1], direction: [0, 0, -1]}", "[70000, 0, 1]");
  ASSERT_TRUE(r.value) << firstError(r);
  EXPECT_TRUE(r.value->rays.rays.empty());
  EXPECT_EQ(r.value->rays.launchRays(), 0u);
}

TEST(Launch, TheSameRayErrorsNameTheLineAndField) {
  struct Bad {
    std::string same, launch, where, message;
  } bad[] = {
      {"{origin: [0, 0, 1], direction: [0, 0, -1]}", "", "t.yaml:3", "rays.same needs rays.launch"},
      {"{origin: [0, 0, 1], direction: [0, 0, -1]}", "[65536, 16384, 2]", "t.yaml:4",
       "at most 2^30 ids in a rays.same launch"},
      {"{origin: [0, 0, 1]}", "[8, 1, 1]", "t.yaml:3",
       "rays.same.direction: missing required key 'direction'"},
      {"{origin: [0, 0, 1], direction: [0, 0, -1], size: 4}", "[8, 1, 1]", "t.yaml:3", "rays.same"},
  };
  for (const Bad& b : bad) {
    const ParseResult r = parseSame(b.same, b.launch);
    EXPECT_FALSE(r.value) << b.same << " " << b.launch;
    const std::string e = firstError(r);
    EXPECT_NE(e.find(b.where), std::string::npos) << e;
    EXPECT_NE(e.find(b.message), std::string::npos) << e;
  }
}

// Above 2^24 ids the model traces one id for all (model/uniform_launch.h):
// the launch size may be read, the launch id not.
TEST(Launch, TheSameRayAbove2To24IdsReadsNoLaunchId) {
  const std::string ray = "{origin: [0, 0, 1], direction: [0, 0, -1]}";
  const ParseResult sized = parseSame(ray, "[131072, 8192, 1]",
                                      "[{if: {eq: [launch_size_y, 8192]}, then: [count: raygen]}]");
  ASSERT_TRUE(sized.value) << firstError(sized);
  EXPECT_EQ(sized.value->rays.launchRays(), uint64_t{1} << 30);
  const ParseResult id =
      parseSame(ray, "[131072, 512, 1]", "[{if: {odd: launch_id_y}, then: [count: raygen]}]");
  EXPECT_FALSE(id.value);
  const std::string e = firstError(id);
  EXPECT_NE(e.find("t.yaml:3"), std::string::npos) << e;
  EXPECT_NE(e.find("rays.launch"), std::string::npos) << e;
  EXPECT_NE(e.find("reads launch_id_x/_y/_z"), std::string::npos) << e;
  EXPECT_TRUE(
      parseSame(ray, "[4096, 4096, 1]", "[{if: {odd: launch_id_y}, then: [count: raygen]}]").value);
}

}  // namespace
}  // namespace rayspec
