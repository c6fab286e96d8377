// Saved runs whose summary.json or results.json says what their bundles do
// not (issue 56 items 7 and 11): `rayspec merge` judges every case anew from
// its bundles and `rayspec compare` checks each bundle's case_hash against
// the case of its name; neither reports the forged verdict.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"
#include "json_files.h"

namespace {
namespace fs = std::filesystem;
using cli::caseArg;
using cli::fresh;
using cli::sh;
using cli::slurp;

const std::string kForged = "anyhit/ignore-odd-primitives";

using testing_support::readJsonFile;
using testing_support::writeJsonFile;

// Two runs of kForged, saved once for every test: one that passes, and one
// with a planted failure judged by a baseline that expects none (so it is
// re-run into <case>/rerun, and fails again).
class Forged : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fresh("forged");
    baseline_ = root_ + "/nothing-expected.csv";
    std::ofstream(baseline_) << "# no failure expected\n";
    good_rc_ =
        sh(cli::kBin + " run --no-validation" + caseArg(kForged) + " --out " + root_ + "/good",
           root_ + "/good.txt");
    failing_rc_ = sh(cli::kBin + " run --no-validation --plant-fault shift-t --baseline " +
                         baseline_ + caseArg(kForged) + " --out " + root_ + "/failing",
                     root_ + "/failing.txt");
  }
  // A copy of a saved run (good or failing) under root_/name.
  static std::string copyOf(const std::string& run, const std::string& name) {
    const std::string dir = root_ + "/" + name;
    fs::remove_all(dir);
    fs::copy(root_ + "/" + run, dir, fs::copy_options::recursive);
    return dir;
  }
  // The shard's summary.json, edited by `edit`.
  template <typename Edit>
  static void editSummary(const std::string& shard, Edit edit) {
    nlohmann::json j = readJsonFile(shard + "/summary.json");
    edit(j);
    writeJsonFile(shard + "/summary.json", j);
  }
  // `rayspec merge SHARD ARGS --out root_/<name>-merged`: exit status and output.
  static std::pair<int, std::string> merged(const std::string& shard, const std::string& name,
                                            const std::string& args = "") {
    const std::string out = root_ + "/" + name + "-merged";
    fs::remove_all(out);
    const int rc =
        sh(cli::kBin + " merge " + shard + args + " --out " + out, root_ + "/" + name + ".txt");
    return {rc, slurp(root_ + "/" + name + ".txt")};
  }
  static std::string root_, baseline_;
  static int good_rc_, failing_rc_;
};
std::string Forged::root_, Forged::baseline_;
int Forged::good_rc_ = -1, Forged::failing_rc_ = -1;

TEST_F(Forged, TheSavedRunsAreWhatTheTestsNeed) {
  ASSERT_EQ(good_rc_, 0) << slurp(root_ + "/good.txt");
  ASSERT_EQ(failing_rc_, 1) << slurp(root_ + "/failing.txt");
  EXPECT_TRUE(fs::exists(root_ + "/failing/" + kForged + "/rerun/device/results.json"));
  EXPECT_NE(slurp(root_ + "/failing.txt").find("running it again"), std::string::npos);
}

// A failing case whose summary.json says Pass: merged as the Fail its
// bundles hold, with a finding quoting what the summary said.
TEST_F(Forged, AFailEditedToPassMergesAsTheFail) {
  const std::string shard = copyOf("failing", "fail-to-pass");
  editSummary(shard, [](nlohmann::json& j) {
    j["cases"][0]["status"] = "Pass";
    j["cases"][0]["headline"] = "Pass";
    j["cases"][0]["findings"] = nlohmann::json::array();
    j["cases"][0]["baseline"] = "";
  });
  const auto [rc, log] = merged(shard, "fail-to-pass");
  EXPECT_EQ(rc, 1) << log;
  const std::string out = root_ + "/fail-to-pass-merged";
  EXPECT_EQ(cli::readDeqpCsv(out + "/results.csv")[kForged], "Fail") << log;
  const nlohmann::json summary = readJsonFile(out + "/summary.json");
  EXPECT_EQ(summary["cases"][0]["status"], "Fail");
  EXPECT_NE(summary["cases"][0].dump().find("summary.json says Pass"), std::string::npos)
      << summary["cases"][0].dump();
}

// The item's own example: the device's bundle holds a validation error, the
// summary says Pass. Merged as a Fail naming the validation message.
TEST_F(Forged, AValidationErrorInTheBundleIsNoPass) {
  const std::string shard = copyOf("good", "validation");
  const std::string json = shard + "/" + kForged + "/device/results.json";
  nlohmann::json j = readJsonFile(json);
  j["validation_messages"] = {"VUID-vkCmdTraceRaysKHR-None-08606: the forged-away error"};
  writeJsonFile(json, j);
  const auto [rc, log] = merged(shard, "validation");
  EXPECT_EQ(rc, 1) << log;
  const std::string out = root_ + "/validation-merged";
  EXPECT_EQ(cli::readDeqpCsv(out + "/results.csv")[kForged], "Fail") << log;
  EXPECT_NE(slurp(out + "/summary.json").find("VUID-vkCmdTraceRaysKHR-None-08606"),
            std::string::npos);
}

// Another device's name in summary.json (for the run, or for the case):
// refused, naming the shard's summary.json, the case and the field.
TEST_F(Forged, AnotherDeviceNameIsRefused) {
  const std::string both = copyOf("good", "device-both");
  editSummary(both, [](nlohmann::json& j) {
    j["device"] = "NVIDIA H100 80GB HBM3 (NVIDIA 550.54.15)";
    j["cases"][0]["device_name"] = "NVIDIA H100 80GB HBM3";
  });
  auto [rc, log] = merged(both, "device-both");
  EXPECT_EQ(rc, 2) << log;
  EXPECT_NE(log.find(both + "/summary.json: case " + kForged + ": device_name 'NVIDIA H100"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("ran on 'llvmpipe"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(root_ + "/device-both-merged/summary.json"));
  const std::string run_only = copyOf("good", "device-run");
  editSummary(run_only,
              [](nlohmann::json& j) { j["device"] = "NVIDIA H100 80GB HBM3 (NVIDIA 550.54.15)"; });
  std::tie(rc, log) = merged(run_only, "device-run");
  EXPECT_EQ(rc, 2) << log;
  EXPECT_NE(log.find(run_only + "/summary.json: device 'NVIDIA H100"), std::string::npos) << log;
  EXPECT_NE(log.find("of case " + kForged + " ran on 'llvmpipe"), std::string::npos) << log;
}

// A failure marked "flake" whose re-run did not differ (or is not in the
// shard) fails the merge under --baseline; a flake only where the re-run's
// bundles gave another result.
TEST_F(Forged, AFlakeNeedsItsRerun) {
  const auto flake = [](nlohmann::json& j) {
    j["cases"][0]["baseline"] = "flake";
    j["cases"][0]["baseline_note"] = "a flake: the re-run gave Pass";
  };
  const std::string again = copyOf("failing", "flake-again");
  editSummary(again, flake);
  auto [rc, log] = merged(again, "flake-again", " --baseline " + baseline_);
  EXPECT_EQ(rc, 1) << log;
  EXPECT_EQ(cli::readDeqpCsv(root_ + "/flake-again-merged/results.csv")[kForged], "Fail") << log;
  const std::string gone = copyOf("failing", "flake-gone");
  editSummary(gone, flake);
  fs::remove_all(gone + "/" + kForged + "/rerun");
  std::tie(rc, log) = merged(gone, "flake-gone", " --baseline " + baseline_);
  EXPECT_EQ(rc, 1) << log;
  EXPECT_NE(slurp(root_ + "/flake-gone-merged/failures.csv").find(kForged + ",Fail"),
            std::string::npos);
  EXPECT_NE(slurp(root_ + "/flake-gone-merged/summary.json").find("holds no re-run of it"),
            std::string::npos);
  // The re-run's bundles those of a run that passed: a flake, which does not fail the merge.
  const std::string real = copyOf("failing", "flake-real");
  for (const char* side : {"device", "model"}) {
    fs::remove_all(real + "/" + kForged + "/rerun/" + side);
    fs::copy(root_ + "/good/" + kForged + "/" + side, real + "/" + kForged + "/rerun/" + side,
             fs::copy_options::recursive);
  }
  std::tie(rc, log) = merged(real, "flake-real", " --baseline " + baseline_);
  EXPECT_EQ(rc, 0) << log;
  EXPECT_EQ(cli::readDeqpCsv(root_ + "/flake-real-merged/results.csv")[kForged], "Flake") << log;
}

// A newline in a baseline note: failures.csv keeps one line per case, and
// no line for the case the note names.
TEST_F(Forged, ANewlineInANoteAddsNoLine) {
  const std::string shard = copyOf("failing", "note-newline");
  editSummary(shard, [](nlohmann::json& j) {
    j["cases"][0]["baseline"] = "flake";
    j["cases"][0]["baseline_note"] = "a flake\nresults/victim,Fail  # forged\n";
  });
  for (const std::string& args : {std::string(), " --baseline " + baseline_}) {
    const auto [rc, log] = merged(shard, "note-newline", args);
    EXPECT_EQ(rc, 1) << args << "\n" << log;
    std::istringstream lines(slurp(root_ + "/note-newline-merged/failures.csv"));
    int cases = 0;
    for (std::string line; std::getline(lines, line);) {
      if (line.empty() || line[0] == '#') continue;
      ++cases;
      EXPECT_EQ(line.rfind(kForged + ",Fail", 0), 0u) << args << ": " << line;
    }
    EXPECT_EQ(cases, 1) << args;
  }
}

// A case whose summary says Pass with no bundle in its folder: nothing shows
// it ran; refused.
TEST_F(Forged, APassWithoutBundlesIsRefused) {
  const std::string shard = copyOf("good", "no-bundles");
  for (const char* side : {"device", "model"}) fs::remove_all(shard + "/" + kForged + "/" + side);
  const auto [rc, log] = merged(shard, "no-bundles");
  EXPECT_EQ(rc, 2) << log;
  EXPECT_NE(log.find("case " + kForged + ": status Pass, but"), std::string::npos) << log;
  EXPECT_NE(log.find("holds no bundle"), std::string::npos) << log;
}

// Shards of a --permute run are judged by the permuted case (its hash).
TEST_F(Forged, APermutedShardMergesByThePermutedCase) {
  const std::string shard = root_ + "/permuted";
  fs::remove_all(shard);
  ASSERT_EQ(
      sh(cli::kBin + " run --no-validation --permute 3" + caseArg(kForged) + " --out " + shard,
         root_ + "/permuted-run.txt"),
      0)
      << slurp(root_ + "/permuted-run.txt");
  const auto [rc, log] = merged(shard, "permuted");
  EXPECT_EQ(rc, 0) << log;
  EXPECT_EQ(cli::readDeqpCsv(root_ + "/permuted-merged/results.csv")[kForged], "Pass") << log;
}

// compare: the case is the one of the bundle's name under --cases, never the
// file results.json names; a case_hash that is not that case's is a CaseError.
TEST_F(Forged, CompareChecksTheCaseHashAndLooksCasesUpByName) {
  const std::string saved = copyOf("good", "compare");
  const std::string bundle = saved + "/" + kForged + "/device";
  const std::string model = saved + "/" + kForged + "/model";
  const auto compared = [&](const std::string& name) {
    const int rc =
        sh(cli::kBin + " compare " + bundle + " " + model + " --out " + root_ + "/" + name + "-out",
           root_ + "/" + name + ".txt");
    return std::pair<int, std::string>{rc, slurp(root_ + "/" + name + ".txt")};
  };
  nlohmann::json j = readJsonFile(bundle + "/results.json");
  const nlohmann::json original = j;
  // Another case's file named: ignored, the case is looked up by its name.
  j["case_file"] = cli::kCases + "results/miss-xor-closest-hit.yaml";
  writeJsonFile(bundle + "/results.json", j);
  auto [rc, log] = compared("compare-file");
  EXPECT_EQ(rc, 0) << log;
  // A case_hash that is not the case's: a CaseError naming the field.
  j = original;
  j["case_hash"] = "0123456789abcdef";
  writeJsonFile(bundle + "/results.json", j);
  std::tie(rc, log) = compared("compare-hash");
  EXPECT_EQ(rc, 1) << log;
  EXPECT_NE(log.find("CaseError"), std::string::npos) << log;
  EXPECT_NE(log.find("case_hash 0123456789abcdef, but the case here"), std::string::npos) << log;
  // The bundle names another case (and its file): judged as that case, the
  // hash is not its; never a pass.
  j = original;
  j["case"] = "results/miss-xor-closest-hit";
  j["case_file"] = cli::kCases + "results/miss-xor-closest-hit.yaml";
  writeJsonFile(bundle + "/results.json", j);
  std::tie(rc, log) = compared("compare-other");
  EXPECT_EQ(rc, 1) << log;
  EXPECT_NE(log.find("CaseError"), std::string::npos) << log;
  // Run folders: A's bundle of a changed case is a CaseError too.
  j = original;
  j["case_hash"] = "0123456789abcdef";
  writeJsonFile(bundle + "/results.json", j);
  rc = sh(cli::kBin + " compare " + saved + " " + root_ + "/good --out " + root_ + "/compare-runs",
          root_ + "/compare-runs.txt");
  log = slurp(root_ + "/compare-runs.txt");
  EXPECT_EQ(rc, 1) << log;
  EXPECT_NE(log.find("case_hash 0123456789abcdef"), std::string::npos) << log;
}

}  // namespace
