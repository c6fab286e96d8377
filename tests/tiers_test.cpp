// The tier runs' helpers (tiers/tier_runs.h); the runs themselves are
// exercised by the ctests cli/stability and cli/accuracy.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "hostile_text.h"
#include "tiers/tier_runs.h"

namespace rayspec {
namespace {

TEST(TierRuns, CasesOfSeveralGlobsEachOnceSorted) {
  RunOptions run;
  run.cases_dir = RAYSPEC_SOURCE_DIR "/cases";
  const std::vector<std::string> names = tierRunCases(
      run, {"watertight/shared-*", "model/*", "watertight/double-hit", "watertight/shared-edges"});
  EXPECT_EQ(names, (std::vector<std::string>{"model/mixed-scene-1024", "watertight/double-hit",
                                             "watertight/shared-edges"}));
  EXPECT_TRUE(tierRunCases(run, {"no-such-family/*"}).empty());
}

TEST(TierRuns, NamesFoldersAndBundles) {
  EXPECT_EQ(tierRunDir("out/runs", "fast"), "out/runs/fast");
  EXPECT_EQ(shortDeviceName("llvmpipe (LLVM 15.0.6, 256 bits) (Mesa 25)"), "llvmpipe");
  EXPECT_EQ(shortDeviceName("NVIDIA H100"), "NVIDIA H100");
  EXPECT_FALSE(readRunBundle("/nonexistent/case/model", "test").has_value());
}

// A saved bundle's device name labels the tables: shown, never obeyed.
TEST(TierRuns, ASavedDeviceNameIsShownNotObeyed) {
  EXPECT_EQ(shortDeviceName("llvmpipe (LLVM 15.0.6, 256 bits)"), "llvmpipe");
  const std::string label = shortDeviceName(testing_support::kHostileText);
  EXPECT_EQ(testing_support::obeyedText(label), "") << label;
  EXPECT_NE(label.find("\\x1B]52;"), std::string::npos) << label;
}

}  // namespace
}  // namespace rayspec
