// A run on a machine that only holds a driver, judged where the full build
// is: the run-only binary (build-device/rayspec, preset `device`, when it has
// been built; else this build's binary with --no-model, and the test says
// which) runs two cases device-only into DIR; `rayspec run --device-results
// DIR` judges them here. A planted fault, an edited results bundle and an
// edited case file must each show; a case that did not run there is
// NotSupported.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"

namespace {
namespace fs = std::filesystem;
using cli::caseArg;
using cli::fresh;
using cli::readDeqpCsv;
using cli::sh;
using cli::slurp;

const std::string kRunOnlyBin = RAYSPEC_DEVICE_BIN;
const std::string kA = "anyhit/ignore-odd-primitives", kB = "results/miss-xor-closest-hit";

bool haveRunOnlyBinary() {
  return fs::exists(kRunOnlyBin);
}

// The device-only run of kA and kB, once for every test.
class DeviceResults : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    saved_ = fresh("device-results-saved");
    const std::string bin =
        haveRunOnlyBinary() ? kRunOnlyBin + " run" : cli::kBin + " run --no-model";
    std::printf("device-only run with: %s\n", bin.c_str());
    rc_ = sh(bin + " --no-validation" + caseArg(kA) + caseArg(kB) + " --out " + saved_,
             saved_ + "/log.txt");
  }
  // `rayspec run --device-results DIR` (the full build) of these cases; its exit status.
  static int judge(const std::string& dir, const std::string& cases, const std::string& out,
                   const std::string& extra = "") {
    return sh(cli::kBin + " run --no-validation --device-results " + dir + cases + " --out " + out +
                  " " + extra,
              out + "/log.txt");
  }
  static std::string saved_;
  static int rc_;
};
std::string DeviceResults::saved_;
int DeviceResults::rc_ = -1;

TEST_F(DeviceResults, TheDeviceOnlyRunComparesNothing) {
  EXPECT_EQ(rc_, 3) << slurp(saved_ + "/log.txt");  // nothing compared
  EXPECT_TRUE(fs::exists(saved_ + "/" + kA + "/device/records.bin"));
  EXPECT_FALSE(fs::exists(saved_ + "/" + kA + "/model"));
  if (haveRunOnlyBinary()) {
    EXPECT_NE(slurp(saved_ + "/log.txt").find("run-only build: no model"), std::string::npos)
        << slurp(saved_ + "/log.txt");
  }
}

TEST_F(DeviceResults, JudgedHereTheyPass) {
  const std::string out = fresh("device-results-judged");
  EXPECT_EQ(judge(saved_, caseArg(kA) + caseArg(kB), out), 0) << slurp(out + "/log.txt");
  const auto status = readDeqpCsv(out + "/results.csv");
  EXPECT_EQ(status.at(kA), "Pass") << slurp(out + "/log.txt");
  EXPECT_EQ(status.at(kB), "Pass");
  // The device is the one that ran there, from the bundles.
  const auto summary = nlohmann::json::parse(slurp(out + "/summary.json"));
  EXPECT_NE(summary.dump().find("llvmpipe"), std::string::npos);
  EXPECT_TRUE(fs::exists(out + "/" + kA + "/model/results.json"));
}

TEST_F(DeviceResults, APlantedFaultInTheLoadedResultsFails) {
  const std::string out = fresh("device-results-fault");
  EXPECT_EQ(judge(saved_, caseArg(kA) + caseArg(kB), out, "--plant-fault shift-t"), 1)
      << slurp(out + "/log.txt");
  const auto status = readDeqpCsv(out + "/results.csv");
  EXPECT_EQ(status.at(kA), "Fail") << slurp(out + "/log.txt");
  EXPECT_EQ(status.at(kB), "Fail");
}

TEST_F(DeviceResults, AnEditedResultsBundleFails) {
  const std::string copy = fresh("device-results-edited"),
                    out = fresh("device-results-edited-judged");
  fs::create_directories(fs::path(copy + "/" + kA).parent_path());
  fs::copy(saved_ + "/" + kA, copy + "/" + kA, fs::copy_options::recursive);
  // Far more miss shader runs than the device reported (a few more could be
  // legal: each ray the model finds ambiguous may take the other path).
  const std::string json = copy + "/" + kA + "/device/results.json";
  auto j = nlohmann::json::parse(slurp(json));
  ASSERT_TRUE(j["counters"].contains("miss")) << j["counters"];
  j["counters"]["miss"] = j["counters"]["miss"].get<uint64_t>() + 100000;
  std::ofstream(json) << j.dump(1);
  EXPECT_EQ(judge(copy, caseArg(kA), out), 1) << slurp(out + "/log.txt");
  EXPECT_EQ(readDeqpCsv(out + "/results.csv").at(kA), "Fail") << slurp(out + "/log.txt");
}

TEST_F(DeviceResults, ACaseThatDidNotRunThereIsNotSupported) {
  const std::string out = fresh("device-results-missing");
  const std::string c = "watertight/shared-edges";
  EXPECT_EQ(judge(saved_, caseArg(kA) + caseArg(c), out), 0) << slurp(out + "/log.txt");
  EXPECT_EQ(readDeqpCsv(out + "/results.csv").at(c),
            "Skip");  // deqp-runner's name for NotSupported
  const auto summary = nlohmann::json::parse(slurp(out + "/summary.json"));
  bool seen = false;
  for (const auto& k : summary["cases"])
    if (k["name"] == c) {
      seen = true;
      EXPECT_EQ(k["status"], "NotSupported");
      EXPECT_NE(k["headline"].get<std::string>().find("did not run there"), std::string::npos)
          << k["headline"];
    }
  EXPECT_TRUE(seen) << summary.dump();
}

TEST_F(DeviceResults, ACaseChangedSinceIsACaseError) {
  const std::string cases = fresh("device-results-cases"), out = fresh("device-results-changed");
  fs::create_directories(cases + "/anyhit");
  std::ofstream(cases + "/" + kA + ".yaml")
      << slurp(cli::kCases + kA + ".yaml") << "\n# edited since it ran\n";
  EXPECT_EQ(judge(saved_, " --cases " + cases, out), 1) << slurp(out + "/log.txt");
  EXPECT_EQ(readDeqpCsv(out + "/results.csv").at(kA), "Fail")
      << "CaseError; deqp-runner has no such name";
  EXPECT_NE(slurp(out + "/summary.txt").find("the case changed since it ran there"),
            std::string::npos)
      << slurp(out + "/summary.txt");
}

TEST_F(DeviceResults, DirEqualToOutIsRefused) {
  EXPECT_EQ(judge(saved_, caseArg(kA), saved_), 2);
  EXPECT_TRUE(fs::exists(saved_ + "/" + kA + "/device/results.json")) << "nothing of it removed";
}

TEST_F(DeviceResults, TheRunOnlyBinaryRefusesWhatNeedsTheModel) {
  if (!haveRunOnlyBinary())
    GTEST_SKIP() << "no " << kRunOnlyBin
                 << " (cmake --preset device; cmake --build --preset device)";
  const std::string out = fresh("device-results-run-only");
  EXPECT_EQ(
      sh(kRunOnlyBin + " run --no-validation --plant-fault shift-t" + caseArg(kA) + " --out " + out,
         out + "/fault.txt"),
      2)
      << slurp(out + "/fault.txt");
  EXPECT_EQ(sh(kRunOnlyBin + " run --device-results " + saved_ + caseArg(kA) + " --out " + out,
               out + "/judge.txt"),
            2)
      << slurp(out + "/judge.txt");
  // A process fault still works there.
  EXPECT_EQ(
      sh(kRunOnlyBin + " run --no-validation --plant-fault crash" + caseArg(kA) + " --out " + out,
         out + "/crash.txt"),
      1)
      << slurp(out + "/crash.txt");
  EXPECT_EQ(readDeqpCsv(out + "/results.csv").at(kA), "Crash");
}

}  // namespace
