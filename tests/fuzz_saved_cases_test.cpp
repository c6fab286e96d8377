// `rayspec fuzz --device-results DIR --saved-cases CASES` (fuzz/saved_cases.h):
// a saved device run is judged against the case text it ran, never the
// generator's regeneration of the seed; a missing text names its file, a text
// other than the one the bundle ran names the bundle's case_hash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

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
  const Result<GeneratedCase> g = savedCase(r.cases, r.device, kSeed, {});
  ASSERT_TRUE(g) << g.error().format();
  EXPECT_EQ(g->yaml, older);
  EXPECT_EQ(g->name, fuzzCaseName(kSeed));
  EXPECT_TRUE(g->features.empty()) << "not this generator's case: no known class matched by it";
}

TEST(SavedCases, TheSameTextKeepsTheGeneratorsFeatures) {
  const GeneratedCase here = generateCase(kSeed);
  const SavedRun r = savedRun("same", here.yaml, here.yaml);
  const Result<GeneratedCase> g = savedCase(r.cases, r.device, kSeed, {});
  ASSERT_TRUE(g) << g.error().format();
  EXPECT_EQ(g->yaml, here.yaml);
  EXPECT_EQ(g->features, here.features);
}

TEST(SavedCases, AMissingTextNamesItsFile) {
  const SavedRun r = savedRun("missing", "", generateCase(kSeed).yaml);
  const Result<GeneratedCase> g = savedCase(r.cases, r.device, kSeed, {});
  ASSERT_FALSE(g);
  const std::string e = g.error().format();
  EXPECT_NE(e.find(r.cases + "/fuzz/seed-5.yaml"), std::string::npos) << e;
  EXPECT_NE(e.find("no saved case text for seed 5"), std::string::npos) << e;
}

TEST(SavedCases, ATextTheBundleDidNotRunNamesItsCaseHash) {
  const std::string ran = generateCase(kSeed).yaml;
  const SavedRun r = savedRun("changed", ran + "# edited after the run\n", ran);
  const Result<GeneratedCase> g = savedCase(r.cases, r.device, kSeed, {});
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
  const Result<GeneratedCase> g = savedCase(r.cases, r.device, kSeed, {});
  ASSERT_TRUE(g) << g.error().format();
  EXPECT_EQ(g->yaml, text);
}

}  // namespace
}  // namespace rayspec
