// `rayspec fuzz --device-results DIR --saved-cases CASES` (fuzz/saved_cases.h):
// a saved device run is judged against the case text it ran, never the
// generator's regeneration of the seed, and classified by what that text
// holds; a missing text names its file, a text other than the one the bundle
// ran names the bundle's case_hash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fuzz/content_features.h"
#include "fuzz/saved_cases.h"
#include "results/content_hash.h"
#include "temp_dir.h"

namespace rayspec {
namespace {

namespace fs = std::filesystem;

constexpr uint64_t kSeed = 5;

void writeText(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
}

struct SavedRun {
  std::string cases, device;
};

// A saved run of seed 5: its case text under cases/, and (unless empty) a
// device bundle under device/ that ran the text whose hash is `ran`.
SavedRun savedRun(const std::string& name, const std::string& text, const std::string& ran) {
  const std::string dir = freshTempDir("fuzz-saved-" + name);
  SavedRun r{dir + "/cases", dir + "/device"};
  fs::create_directories(r.cases);
  fs::create_directories(r.device);
  if (!text.empty()) writeText(fs::path(r.cases) / (fuzzCaseName(kSeed) + ".yaml"), text);
  if (!ran.empty())
    writeText(fs::path(r.device) / fuzzCaseName(kSeed) / "device" / "results.json",
              "{\"case\": \"" + fuzzCaseName(kSeed) + "\", \"case_hash\": \"" +
                  contentHashText(contentHash(ran)) + "\"}");
  return r;
}

TEST(SavedCases, TheTextThatRanIsJudgedNotTheRegeneration) {
  // As an older generator made it: another text than this build's for the seed.
  const std::string older = generateCase(kSeed).yaml + "# made by an older generator\n";
  const SavedRun r = savedRun("older", older, older);
  const Result<GeneratedCase> g = savedCase(r.cases, r.device, kSeed);
  ASSERT_TRUE(g) << g.error().format();
  EXPECT_EQ(g->yaml, older);
  EXPECT_EQ(g->name, fuzzCaseName(kSeed));
}

// A saved text this build's generator does not make again from its seed is
// classified by what it holds (the Mesa 26.2.6 hour of 2026-12-07: 7 cases
// of known classes counted new, their texts made before a generator change):
// each feature a known class may key on, in a text of another seed saved
// as seed 5's, with a line of its own.
TEST(SavedCases, AnOlderTextIsClassifiedByWhatItHolds) {
  for (const std::string& feature : contentFeatureNames()) {
    uint64_t seed = 1;
    while (seed < 2000 && !generateCase(seed).features.count(feature)) ++seed;
    ASSERT_LT(seed, 2000u) << "no seed draws " << feature;
    const std::string older = generateCase(seed).yaml + "# made by an older generator\n";
    const SavedRun r = savedRun("older-" + feature, older, older);
    const Result<GeneratedCase> g = savedCase(r.cases, r.device, kSeed);
    ASSERT_TRUE(g) << g.error().format();
    EXPECT_NE(g->yaml, generateCase(kSeed).yaml);
    EXPECT_TRUE(g->features.count(feature)) << feature << " (seed " << seed << "'s text)";
  }
}

TEST(SavedCases, AMissingTextNamesItsFile) {
  const SavedRun r = savedRun("missing", "", generateCase(kSeed).yaml);
  const Result<GeneratedCase> g = savedCase(r.cases, r.device, kSeed);
  ASSERT_FALSE(g);
  const std::string e = g.error().format();
  EXPECT_NE(e.find(r.cases + "/fuzz/seed-5.yaml"), std::string::npos) << e;
  EXPECT_NE(e.find("no saved case text for seed 5"), std::string::npos) << e;
}

TEST(SavedCases, ATextTheBundleDidNotRunNamesItsCaseHash) {
  const std::string ran = generateCase(kSeed).yaml;
  const SavedRun r = savedRun("changed", ran + "# edited after the run\n", ran);
  const Result<GeneratedCase> g = savedCase(r.cases, r.device, kSeed);
  ASSERT_FALSE(g);
  const std::string e = g.error().format();
  EXPECT_NE(e.find(r.device + "/fuzz/seed-5/device/results.json"), std::string::npos) << e;
  EXPECT_NE(e.find("case_hash: " + contentHashText(contentHash(ran))), std::string::npos) << e;
  EXPECT_NE(e.find("the device ran another text than the one saved"), std::string::npos) << e;
}

TEST(SavedCases, ASeedWithNoBundleIsLeftToTheRun) {
  // Not run there: the run loop says NotSupported; the text is still the saved one.
  const std::string text = generateCase(kSeed).yaml;
  const SavedRun r = savedRun("unrun", text, "");
  const Result<GeneratedCase> g = savedCase(r.cases, r.device, kSeed);
  ASSERT_TRUE(g) << g.error().format();
  EXPECT_EQ(g->yaml, text);
}

}  // namespace
}  // namespace rayspec
