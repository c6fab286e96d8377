// `rayspec fuzz --without`: the device features the generator leaves out.
// Without VK_KHR_ray_query no generated case needs it (as the check the
// Vulkan engine runs before a case decides, vulkan/case_support.h), the same
// seed still makes one case, and the rest of the case varies as before:
// where the default case drew no ray query, the case is the same.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "device_info_support.h"
#include "fuzz/content_features.h"
#include "fuzz/generate_case.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "run/library_support.h"

namespace rayspec {
namespace {

GeneratorFeatures withoutRayQuery() {
  GeneratorFeatures f;
  EXPECT_TRUE(leaveOut(f, "VK_KHR_ray_query"));
  return f;
}

const std::set<std::string> kRayQueryFeatures = {
    "ray-query", "ray-query-generate", "ray-query-terminate", "traces-ray-query", "traces-compute"};

// The generated cases of seeds [first, first + n) that parse, as library
// cases (their plans), for the device-support check.
std::vector<LibraryCase> parsedCases(uint64_t first, uint64_t n, const GeneratorFeatures& allowed) {
  std::vector<LibraryCase> cases;
  for (uint64_t seed = first; seed < first + n; ++seed) {
    const GeneratedCase g = generateCase(seed, allowed);
    const ParseResult p = parseCaseText(g.yaml, g.name + ".yaml", g.name);
    if (p.value && p.errors.empty()) cases.push_back({*p.value, derivePlan(*p.value)});
  }
  return cases;
}

// How many of `cases` a device without each leavable feature alone cannot
// run, by the feature's name.
std::map<std::string, int> skipsByFeature(const std::vector<LibraryCase>& cases) {
  DeviceInfo d = capableDevice();
  const std::string names = leavableFeatureNames();
  for (const auto& [label, member] : featureRows())
    if (names.find(label) != std::string::npos) d.*member = false;
  std::map<std::string, int> skips;
  for (const FeatureSkips& f : librarySupport(cases, d, 0).missing) skips[f.feature] = f.cases;
  EXPECT_EQ(skips.size(), 6u) << names;
  return skips;
}

const std::vector<std::string> kSizedFeatures = {"shaderInt8", "shaderInt16", "shaderInt64",
                                                 "shaderFloat16", "shaderFloat64"};

TEST(FuzzWithout, NamesAreTheDeviceRows) {
  EXPECT_EQ(leavableFeatureNames(),
            "VK_KHR_ray_query, shaderInt8, shaderInt16, shaderInt64, shaderFloat16, shaderFloat64");
  GeneratorFeatures f;
  EXPECT_EQ(leftOutText(f), "");
  const Result<void> unknown = leaveOut(f, "ray-query");
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().format().find("'ray-query'"), std::string::npos);
  EXPECT_NE(unknown.error().format().find("VK_KHR_ray_query"), std::string::npos);
  // A row the generator never draws is no name --without takes.
  EXPECT_FALSE(leaveOut(f, "VK_KHR_pipeline_library"));
  EXPECT_TRUE(f.ray_query);
  ASSERT_TRUE(leaveOut(f, "VK_KHR_ray_query"));
  EXPECT_FALSE(f.ray_query);
  EXPECT_EQ(leftOutText(f), "without VK_KHR_ray_query");
  // The sized types by the feature of their row (a vector's: its component's).
  EXPECT_TRUE(allowsType(f, ValueType::Int8Vec3));
  ASSERT_TRUE(leaveOut(f, "shaderInt8"));
  EXPECT_FALSE(allowsType(f, ValueType::Int8Vec3));
  EXPECT_FALSE(allowsType(f, ValueType::Uint8));
  EXPECT_TRUE(allowsType(f, ValueType::Int16));
  EXPECT_TRUE(allowsType(f, ValueType::Int32));
  EXPECT_TRUE(allowsType(f, ValueType::UintVec3));
  EXPECT_EQ(leftOutText(f), "without VK_KHR_ray_query, shaderInt8");
}

// The check a device runs before each case: by default some cases need
// each leavable feature (so the counts can fail), without them all none
// does, and typed state of the types no feature gates (int32, ivec, uvec) is
// still drawn. 2 x 200 cases: about 5 s.
TEST(FuzzWithout, NoCaseNeedsALeftOutFeature) {
  std::map<std::string, int> skips = skipsByFeature(parsedCases(1, 200, {}));
  EXPECT_GT(skips["VK_KHR_ray_query"], 40);
  for (const std::string& f : kSizedFeatures) EXPECT_GE(skips[f], 8) << f;
  GeneratorFeatures none = withoutRayQuery();
  for (const std::string& f : kSizedFeatures) ASSERT_TRUE(leaveOut(none, f));
  const std::vector<LibraryCase> without = parsedCases(1, 200, none);
  EXPECT_GE(without.size(), 195u);
  for (const auto& [feature, cases] : skipsByFeature(without)) EXPECT_EQ(cases, 0) << feature;
  size_t typed = 0;
  for (const LibraryCase& l : without) {
    EXPECT_FALSE(l.plan.ray_queries) << l.c.name;
    EXPECT_FALSE(l.c.pipeline.ray_query || l.c.pipeline.ray_query_in_hit) << l.c.name;
    typed += contentFeatures(l.c).count("sized-values");
  }
  EXPECT_GE(typed, 20u);
}

// One sized type's feature left out, the others' types are still drawn.
// 100 cases: about 1 s.
TEST(FuzzWithout, OneSizedFeatureLeavesTheOthers) {
  GeneratorFeatures no64;
  ASSERT_TRUE(leaveOut(no64, "shaderInt64"));
  std::map<std::string, int> skips = skipsByFeature(parsedCases(1, 100, no64));
  EXPECT_EQ(skips["shaderInt64"], 0);
  for (const char* f : {"shaderInt8", "shaderInt16", "shaderFloat16", "shaderFloat64"})
    EXPECT_GE(skips[f], 4) << f;
}

TEST(FuzzWithout, SameSeedSameCase) {
  for (uint64_t seed : {3ull, 5ull, 90ull}) {
    const GeneratedCase a = generateCase(seed, withoutRayQuery());
    EXPECT_EQ(a.yaml, generateCase(seed, withoutRayQuery()).yaml);
    EXPECT_NE(
        a.yaml.find("generated from seed " + std::to_string(seed) + " without VK_KHR_ray_query\n"),
        std::string::npos);
  }
}

// Where the default case drew no ray query, the case without them is the
// same case (but for its description); the others differ in their queries.
TEST(FuzzWithout, OnlyTheQueriesChange) {
  size_t same = 0, changed = 0;
  for (uint64_t seed = 1; seed <= 200; ++seed) {
    const GeneratedCase d = generateCase(seed), w = generateCase(seed, withoutRayQuery());
    for (const std::string& f : w.features) EXPECT_EQ(kRayQueryFeatures.count(f), 0u) << f;
    bool queries = false;
    for (const std::string& f : d.features) queries = queries || kRayQueryFeatures.count(f);
    std::string expected = d.yaml;
    const std::string line = "generated from seed " + std::to_string(seed);
    expected.insert(expected.find(line) + line.size(), " without VK_KHR_ray_query");
    if (queries) {
      EXPECT_NE(w.yaml, expected) << seed;
      ++changed;
    } else {
      EXPECT_EQ(w.yaml, expected) << seed;
      ++same;
    }
  }
  EXPECT_GT(same, 50u);
  EXPECT_GT(changed, 40u);
}

// The pipeline's other programs still vary: every feature of the generator
// but the ray queries' shows in seeds 0..199 (as SeedsCoverEveryFeature).
TEST(FuzzWithout, TheRestStillVaries) {
  std::map<std::string, size_t> seen;
  std::set<std::string> pipelines;
  for (uint64_t seed = 0; seed < 200; ++seed) {
    const GeneratedCase g = generateCase(seed, withoutRayQuery());
    for (const std::string& f : g.features) ++seen[f];
    pipelines.insert(g.yaml.substr(g.yaml.find("\npipeline:")));
  }
  for (const std::string& f : generatorFeatures()) {
    if (!kRayQueryFeatures.count(f)) {
      EXPECT_GE(seen[f], 5u) << f;
    }
  }
  EXPECT_EQ(pipelines.size(), 200u);
}

}  // namespace
}  // namespace rayspec
