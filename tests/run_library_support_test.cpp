// `rayspec devices`' account of a device (issue 61): the library cases each
// missing feature keeps from running, decided by the check the Vulkan
// engine runs before a case (vulkan/case_support.h), and the text it prints
// of a device's identity, the validation layer and those counts.
#include <gtest/gtest.h>

#include <filesystem>

#include "device_info_support.h"
#include "run/device_description.h"
#include "run/library_support.h"

namespace rayspec {
namespace {
namespace fs = std::filesystem;

constexpr uint32_t kLayer239 = kTestVulkan13 | 239;  // Debian 12's validation layer

// Four library cases in a folder of their own: one plain, one skipping
// triangles (rayTraversalPrimitiveCulling), two ray query ones (VK_KHR_ray_query),
// one of which reads vertex positions (position fetch, 1.3.249).
std::vector<LibraryCase> fourCases() {
  const std::string dir = ::testing::TempDir() + "/library-support";
  fs::remove_all(dir);
  for (const char* name : {"results/miss-xor-closest-hit", "culling/skip-pipeline-flags",
                           "ray-query/query-in-function", "ray-query/position-fetch"}) {
    fs::create_directories(fs::path(dir + "/" + name).parent_path());
    fs::copy_file(std::string(RAYSPEC_SOURCE_DIR) + "/cases/" + name + ".yaml",
                  dir + "/" + name + ".yaml");
  }
  return libraryCases(dir);
}

const FeatureSkips* skipsOf(const LibrarySupport& s, const std::string& feature) {
  for (const FeatureSkips& f : s.missing)
    if (f.feature == feature) return &f;
  return nullptr;
}

TEST(LibrarySupport, ACapableDeviceRunsEveryCase) {
  const std::vector<LibraryCase> cases = fourCases();
  ASSERT_EQ(cases.size(), 4u);
  const LibrarySupport s = librarySupport(cases, capableDevice(), 0);
  EXPECT_EQ(s.cases, 4);
  EXPECT_EQ(s.not_supported, 0);
  EXPECT_TRUE(s.missing.empty());
}

TEST(LibrarySupport, EachMissingFeatureCountsTheCasesItAloneSkips) {
  const std::vector<LibraryCase> cases = fourCases();
  DeviceInfo d = capableDevice();
  d.ray_traversal_primitive_culling = d.ray_query = d.opacity_micromap = false;
  const LibrarySupport s = librarySupport(cases, d, 0);
  EXPECT_EQ(s.not_supported, 3);
  ASSERT_EQ(s.missing.size(), 3u);
  ASSERT_TRUE(skipsOf(s, "rayTraversalPrimitiveCulling"));
  EXPECT_EQ(skipsOf(s, "rayTraversalPrimitiveCulling")->cases, 1);
  ASSERT_TRUE(skipsOf(s, "VK_KHR_ray_query"));
  EXPECT_EQ(skipsOf(s, "VK_KHR_ray_query")->cases, 2);
  ASSERT_TRUE(skipsOf(s, "VK_EXT_opacity_micromap"));
  EXPECT_EQ(skipsOf(s, "VK_EXT_opacity_micromap")->cases, 0);
  // Without position fetch the ray query case that reads positions counts
  // under both of the features it lacks.
  d.position_fetch = false;
  const LibrarySupport both = librarySupport(cases, d, 0);
  EXPECT_EQ(both.not_supported, 3);
  EXPECT_EQ(skipsOf(both, "VK_KHR_ray_tracing_position_fetch")->cases, 1);
  EXPECT_EQ(skipsOf(both, "VK_KHR_ray_query")->cases, 2);
}

// A validation layer older than position fetch (1.3.249) makes the case that
// reads positions NotSupported while it is on; off (0), the case runs.
TEST(LibrarySupport, AnOldValidationLayerSkipsThePositionFetchCase) {
  const std::vector<LibraryCase> cases = fourCases();
  const LibrarySupport on = librarySupport(cases, capableDevice(), kLayer239);
  EXPECT_EQ(on.not_supported, 1);
  ASSERT_EQ(on.missing.size(), 1u);
  EXPECT_TRUE(on.missing[0].validation_layer);
  EXPECT_EQ(on.missing[0].feature, "1.3.239");
  EXPECT_EQ(on.missing[0].cases, 1);
  const LibrarySupport newer = librarySupport(cases, capableDevice(), kTestVulkan13 | 250);
  EXPECT_EQ(newer.not_supported, 0);
  EXPECT_TRUE(newer.missing.empty());
}

TEST(DeviceDescription, IdentityLines) {
  DeviceInfo d;
  d.conformance_version = "1.3.1.1";
  d.driver_id = "MesaLlvmpipe (13)";
  d.device_uuid = "00aa-11bb";
  d.pipeline_cache_uuid = "22cc";
  EXPECT_EQ(
      deviceIdentityLines(d),
      (std::vector<std::string>{"conformance version 1.3.1.1, driver ID MesaLlvmpipe (13)",
                                "device UUID 00aa, driver UUID 11bb", "pipeline cache UUID 22cc"}));
  EXPECT_EQ(deviceIdentityLines(DeviceInfo{}),
            (std::vector<std::string>{"conformance version not reported, driver ID not reported",
                                      "device UUID not reported, driver UUID not reported",
                                      "pipeline cache UUID not reported"}));
}

TEST(DeviceDescription, ValidationLayerLine) {
  EXPECT_NE(validationLayerLine(0, false).find("Validation layer: not installed"),
            std::string::npos);
  const std::string on = validationLayerLine(kLayer239, false);
  EXPECT_NE(on.find("VK_LAYER_KHRONOS_validation 1.3.239 (on in runs;"), std::string::npos) << on;
  EXPECT_NE(on.find("--no-validation runs it"), std::string::npos) << on;
  EXPECT_NE(validationLayerLine(kLayer239, true).find("1.3.239 (off: --no-validation)"),
            std::string::npos);
}

TEST(DeviceDescription, LibrarySupportLines) {
  LibrarySupport s;
  s.cases = 1607;
  s.not_supported = 9;
  s.missing = {{"rayTraversalPrimitiveCulling", 3, false},
               {"VK_EXT_opacity_micromap", 0, false},
               {"accelerationStructureHostCommands", 0, false},
               {"1.3.239", 6, true}};
  EXPECT_EQ(librarySupportLines(s),
            (std::vector<std::string>{
                "library: 9 of 1607 cases NotSupported here",
                "  3 cases for lack of rayTraversalPrimitiveCulling",
                "  6 cases under the validation layer 1.3.239 (older than an extension they use; "
                "--no-validation runs them)",
                "  lacks also VK_EXT_opacity_micromap, accelerationStructureHostCommands: no case "
                "needs them"}));
  s.missing = {{"VK_KHR_ray_query", 1, false}};
  s.not_supported = 1;
  s.cases = 1;
  EXPECT_EQ(librarySupportLines(s),
            (std::vector<std::string>{"library: 1 of 1 case NotSupported here",
                                      "  1 case for lack of VK_KHR_ray_query"}));
}

}  // namespace
}  // namespace rayspec
