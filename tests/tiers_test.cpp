// The tier runs' helpers (tiers/tier_runs.h); the runs themselves are
// exercised by the ctests cli/stability and cli/accuracy.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tiers/tier_runs.h"

namespace rayspec {
namespace {

TEST(TierRuns, CasesOfSeveralGlobsEachOnceSorted) {
  RunOptions run;
  run.cases_dir = RAYSPEC_SOURCE_DIR "/cases";
  const std::vector<std::string> names =
      tierRunCases(run, {"watertight/*", "model/*", "watertight/shared-edges"});
  EXPECT_EQ(names,
            (std::vector<std::string>{"model/mixed-scene-1024", "watertight/double-hit",
                                      "watertight/ignored-edge-floor", "watertight/shared-edges"}));
  EXPECT_TRUE(tierRunCases(run, {"no-such-family/*"}).empty());
}

TEST(TierRuns, NamesFoldersAndBundles) {
  EXPECT_EQ(tierRunDir("out/runs", "fast"), "out/runs/fast");
  EXPECT_EQ(shortDeviceName("llvmpipe (LLVM 15.0.6, 256 bits) (Mesa 25)"), "llvmpipe");
  EXPECT_EQ(shortDeviceName("NVIDIA H100"), "NVIDIA H100");
  EXPECT_FALSE(readRunBundle("/nonexistent/case/model", "test").has_value());
}

}  // namespace
}  // namespace rayspec
