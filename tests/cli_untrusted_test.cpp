// Saved runs, bundles and options as a hostile user writes them (issue 24):
// names that would lead outside --out, image files shorter than results.json
// says, output folders that cannot be one. Each ends in a clear error naming
// the file and field (or option) and nothing outside the run's folders is
// touched.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"
#include "json_files.h"

namespace {
namespace fs = std::filesystem;
using cli::caseArg;
using cli::fresh;
using cli::sh;
using cli::slurp;
using cli::victim;

const std::string kImages = "anyhit/ignore-odd-primitives";  // a case with images

using testing_support::readJsonFile;
using testing_support::writeJsonFile;

// One run of kImages, device and model, saved once for every test.
class Untrusted : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fresh("untrusted");
    rc_ = sh(cli::kBin + " run --no-validation" + caseArg(kImages) + " --out " + root_ + "/run",
             root_ + "/run.txt");
  }
  // A copy of the saved run under root_/name.
  static std::string copyRun(const std::string& name) {
    const std::string dir = root_ + "/" + name;
    fs::remove_all(dir);
    fs::copy(root_ + "/run", dir, fs::copy_options::recursive);
    return dir;
  }
  // `rayspec run --device-results saved` of kImages into root_/<name>-judged:
  // its exit status and output.
  static std::pair<int, std::string> judged(const std::string& saved, const std::string& name) {
    const std::string out = root_ + "/" + name + "-judged";
    fs::remove_all(out);
    const int rc = sh(cli::kBin + " run --no-validation --device-results " + saved +
                          caseArg(kImages) + " --out " + out,
                      root_ + "/" + name + ".txt");
    return {rc, slurp(root_ + "/" + name + ".txt")};
  }
  static std::string root_;
  static int rc_;
};
std::string Untrusted::root_;
int Untrusted::rc_ = -1;

TEST_F(Untrusted, TheSavedRunPasses) {
  ASSERT_EQ(rc_, 0) << slurp(root_ + "/run.txt");
}

// An image named ../../../../evil/y in a saved device bundle: a CaseError
// naming results.json and the image name; no y.raw read, no y.png written.
TEST_F(Untrusted, AnImageNameThatClimbsIsACaseError) {
  const std::string saved = copyRun("image-climbs");
  const std::string json = saved + "/" + kImages + "/device/results.json";
  nlohmann::json j = readJsonFile(json);
  ASSERT_FALSE(j["images"].empty());
  const std::string raw =
      saved + "/" + kImages + "/device/" + j["images"][0]["name"].get<std::string>() + ".raw";
  j["images"][0]["name"] = "../../../../evil/y";
  writeJsonFile(json, j);
  fs::create_directories(root_ + "/evil");
  fs::copy_file(raw, root_ + "/evil/y.raw", fs::copy_options::overwrite_existing);
  const auto [rc, log] = judged(saved, "image-climbs");
  EXPECT_EQ(rc, 1) << log;
  EXPECT_NE(log.find("CaseError"), std::string::npos) << log;
  EXPECT_NE(log.find("results.json: images: name '../../../../evil/y'"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(root_ + "/evil/y.png"));
}

// An image .raw shorter than width x height x channels: a CaseError naming
// the file and both sizes (it was a SIGSEGV of the judging process).
TEST_F(Untrusted, AShortImageIsACaseErrorNamingTheSizes) {
  const std::string saved = copyRun("image-short");
  const std::string dir = saved + "/" + kImages + "/device/";
  const nlohmann::json j = readJsonFile(dir + "results.json");
  const std::string raw = dir + j["images"][0]["name"].get<std::string>() + ".raw";
  fs::resize_file(raw, fs::file_size(raw) / 2);
  const auto [rc, log] = judged(saved, "image-short");
  EXPECT_EQ(rc, 1) << log;
  EXPECT_NE(log.find(".raw holds " + std::to_string(fs::file_size(raw)) +
                     " bytes; results.json says image"),
            std::string::npos)
      << log;
}

// A bundle whose results.json names the case ../victim: compare refuses it
// and the folder beside --out survives (compare removed it recursively).
TEST_F(Untrusted, CompareNeverRemovesAFolderABundleNames) {
  const std::string saved = copyRun("compare-climbs");
  const std::string bundle = saved + "/" + kImages + "/device";
  nlohmann::json j = readJsonFile(bundle + "/results.json");
  j["case"] = "../victim";
  writeJsonFile(bundle + "/results.json", j);
  const std::string kept = victim(root_, "victim");
  const std::string out = root_ + "/compare-out";
  const int rc =
      sh(cli::kBin + " compare " + bundle + " " + saved + "/" + kImages + "/model --out " + out,
         root_ + "/compare-climbs.txt");
  const std::string log = slurp(root_ + "/compare-climbs.txt");
  EXPECT_NE(rc, 0) << log;
  EXPECT_NE(log.find("'../victim' is no case name"), std::string::npos) << log;
  EXPECT_TRUE(fs::exists(kept + "/keep.txt"));
}

// A shard whose summary.json names a case ../victim2: merge exits 2 naming
// the file, and the folder beside --out survives.
TEST_F(Untrusted, MergeNeverRemovesAFolderASummaryNames) {
  const std::string shard = copyRun("merge-climbs");
  nlohmann::json j = readJsonFile(shard + "/summary.json");
  ASSERT_FALSE(j["cases"].empty());
  j["cases"][0]["name"] = "../victim2";
  writeJsonFile(shard + "/summary.json", j);
  const std::string kept = victim(root_, "victim2");
  const std::string out = root_ + "/merge-out";
  const int rc = sh(cli::kBin + " merge " + shard + " --out " + out, root_ + "/merge-climbs.txt");
  const std::string log = slurp(root_ + "/merge-climbs.txt");
  EXPECT_EQ(rc, 2) << log;
  EXPECT_NE(log.find("summary.json: cases: name '../victim2' is no case name"), std::string::npos)
      << log;
  EXPECT_TRUE(fs::exists(kept + "/keep.txt"));
}

// A run removes only what it writes in a case's folder: a folder kept there
// survives a run into the same --out.
TEST_F(Untrusted, ARunRemovesOnlyWhatItWrote) {
  const std::string out = root_ + "/kept";
  fs::remove_all(out);
  const std::string kept = victim(out + "/" + kImages, "notes");
  const int rc = sh(cli::kBin + " run --no-validation" + caseArg(kImages) + " --out " + out,
                    root_ + "/kept.txt");
  EXPECT_EQ(rc, 0) << slurp(root_ + "/kept.txt");
  EXPECT_TRUE(fs::exists(kept + "/keep.txt"));
  EXPECT_TRUE(fs::exists(out + "/" + kImages + "/device/results.json"));
}

// A shard that stopped early is no passing merge: exit 1, saying so.
TEST_F(Untrusted, MergingAnInterruptedShardIsNoPass) {
  const std::string shard = copyRun("merge-interrupted");
  nlohmann::json j = readJsonFile(shard + "/summary.json");
  j["interrupted"] = true;
  j["planned_cases"] = 2;
  writeJsonFile(shard + "/summary.json", j);
  const int rc = sh(cli::kBin + " merge " + shard + " --out " + root_ + "/merge-interrupted-out",
                    root_ + "/merge-interrupted.txt");
  const std::string log = slurp(root_ + "/merge-interrupted.txt");
  EXPECT_EQ(rc, 1) << log;
  EXPECT_NE(log.find("INTERRUPTED: 1 of 2 planned cases ran"), std::string::npos) << log;
}

// --resume with a narrower selection would drop the cases it does not select
// from results.csv and summary.json: refused, naming one of them.
TEST_F(Untrusted, ResumeRefusesANarrowerSelection) {
  const std::string out = root_ + "/resume";
  fs::remove_all(out);
  const std::string two = caseArg(kImages) + caseArg("results/miss-xor-closest-hit");
  ASSERT_EQ(sh(cli::kBin + " run --no-validation" + two + " --out " + out, root_ + "/resume-1.txt"),
            0)
      << slurp(root_ + "/resume-1.txt");
  const int rc =
      sh(cli::kBin + " run --no-validation --resume" + caseArg(kImages) + " --out " + out,
         root_ + "/resume-2.txt");
  const std::string log = slurp(root_ + "/resume-2.txt");
  EXPECT_EQ(rc, 2) << log;
  EXPECT_NE(log.find("holds 1 case(s) this run does not select (results/miss-xor-closest-hit)"),
            std::string::npos)
      << log;
  EXPECT_NE(slurp(out + "/results.csv").find("results/miss-xor-closest-hit"), std::string::npos);
}

// Output folders and numbers that cannot be used: exit 2 before anything runs.
TEST_F(Untrusted, UnusableOptionsAreExit2AtTheStart) {
  const std::string file = root_ + "/a-file";
  std::ofstream(file) << "x";
  const std::vector<std::string> bad = {"run --out ''",
                                        "run --out /",
                                        "run --out " + file,
                                        "stability --out ''",
                                        "stability --out " + file,
                                        "accuracy --out " + file,
                                        "run --timeout 0",
                                        "run --timeout -5",
                                        "run --timeout nan",
                                        "run --permute -1",
                                        "run --permute 18446744073709551616",
                                        "run --memory-limit 100M",
                                        "run --move=x,y,z,0,0,0.1"};
  for (const std::string& args : bad) {
    const int rc =
        sh(cli::kBin + " " + args + " --no-device --filter 'none/*'", root_ + "/options.txt");
    const std::string log = slurp(root_ + "/options.txt");
    EXPECT_EQ(rc, 2) << args << ": " << log;
    EXPECT_EQ(log.find("Reports:"), std::string::npos) << args << ": " << log;
  }
  EXPECT_FALSE(fs::exists("/summary.json"));
}

// Issue 56, items 14 and 16: a number is what it is written as. A sign, a
// space, "0x" or a value past 64 bits is exit 2 naming the option, never
// read as another number (-1 as no limit, 0x10 as 16 bytes).
TEST_F(Untrusted, NumbersAreTakenOnlyAsWritten) {
  const std::string spaces(100000, ' ');
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"--memory-limit -1", "--memory-limit"},
      {"--memory-limit 0x10", "--memory-limit"},
      {"--memory-limit 18446744073709551616", "--memory-limit"},
      {"--memory-limit 99999999999999999T", "--memory-limit"},
      {"--memory-limit ' 8G'", "--memory-limit"},
      {"--timeout ' 5'", "--timeout"},
      {"--timeout 0x10", "--timeout"},
      {"--timeout 1e3", "--timeout"},
      {"--jobs ' 2'", "--jobs"},
      {"--jobs 0x2", "--jobs"},
      {"--jobs -1", "--jobs"},
      {"--threads +1", "--threads"},
      {"--shard '" + spaces + "1/2'", "--shard"},
      {"--shard '1 / 2'", "--shard"}};
  for (const auto& [args, option] : bad) {
    const int rc = sh(
        cli::kBin + " run --no-device " + args + caseArg(kImages) + " --out " + root_ + "/numbers",
        root_ + "/numbers.txt");
    const std::string log = slurp(root_ + "/numbers.txt");
    EXPECT_EQ(rc, 2) << args.substr(0, 60) << ": " << log.substr(0, 400);
    EXPECT_NE(log.find(option), std::string::npos)
        << args.substr(0, 60) << ": " << log.substr(0, 400);
    EXPECT_LT(log.size(), 2000u) << args.substr(0, 60);
    EXPECT_EQ(log.find("Reports:"), std::string::npos) << args.substr(0, 60);
  }
  // Plain numbers, with and without units, still run.
  const int rc =
      sh(cli::kBin + " run --no-device --memory-limit 512M --timeout 2.5 --jobs 1 " +
             "--threads 1 --shard 1/1" + caseArg(kImages) + " --out " + root_ + "/numbers",
         root_ + "/numbers.txt");
  EXPECT_NE(rc, 2) << slurp(root_ + "/numbers.txt");
  EXPECT_NE(slurp(root_ + "/numbers.txt").find("Reports:"), std::string::npos);
}

}  // namespace
