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

// How many of `cases` a device without VK_KHR_ray_query alone cannot run.
int raysQuerySkips(const std::vector<LibraryCase>& cases) {
  DeviceInfo d = capableDevice();
  d.ray_query = false;
  const LibrarySupport s = librarySupport(cases, d, 0);
  for (const FeatureSkips& f : s.missing)
    if (f.feature == "VK_KHR_ray_query") return f.cases;
  ADD_FAILURE() << "no VK_KHR_ray_query row";
  return -1;
}

TEST(FuzzWithout, NamesAreTheDeviceRows) {
  EXPECT_EQ(leavableFeatureNames(), "VK_KHR_ray_query");
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
}

// The check a device runs before each case: by default some cases need
// VK_KHR_ray_query (so the count can fail), without it none does.
TEST(FuzzWithout, NoCaseNeedsRayQuery) {
  EXPECT_GT(raysQuerySkips(parsedCases(1, 200, {})), 40);
  const std::vector<LibraryCase> without = parsedCases(1, 200, withoutRayQuery());
  EXPECT_GE(without.size(), 195u);
  EXPECT_EQ(raysQuerySkips(without), 0);
  for (const LibraryCase& l : without) {
    EXPECT_FALSE(l.plan.ray_queries) << l.c.name;
    EXPECT_FALSE(l.c.pipeline.ray_query || l.c.pipeline.ray_query_in_hit) << l.c.name;
  }
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
