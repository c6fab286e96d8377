// The regression gate as a driver team's CI uses it: `rayspec run --baseline`
// with flakes and skips files, re-runs of unexpected failures, failures.csv,
// shards (--shard, GoogleTest's variables) and `rayspec merge`.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"

namespace {
namespace fs = std::filesystem;
using cli::caseArg;
using cli::fresh;
using cli::kBin;
using cli::readDeqpCsv;
using cli::sh;
using cli::slurp;

// Three cheap cases; b stands for the driver's known bug (a planted fault).
const std::string kA = "results/miss-xor-closest-hit", kB = "anyhit/ignore-odd-primitives",
                  kC = "culling/cull-opaque";
const std::string kThree = caseArg(kA) + caseArg(kB) + caseArg(kC);

std::string write(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

// A baseline round trip: the known failure passes the gate, a new failure
// fails it (and is re-run, and written to failures.csv), a fixed failure is
// an unexpected pass that fails it until the baseline is updated.
TEST(Gate, BaselineRoundTrip) {
  const std::string dir = fresh("gate");
  const std::string baseline = write(dir + "/driver.csv", kB + ",Fail  # the driver's known bug\n");
  const std::string run = kBin + " run --no-validation" + kThree + " --baseline " + baseline;

  // The known bug, as the baseline says: exit 0, ExpectedFail.
  ASSERT_EQ(sh(run + " --plant-fault shift-t --plant-fault-in " + kB + " --out " + dir + "/known",
               dir + "/known.txt"),
            0)
      << slurp(dir + "/known.txt");
  auto status = readDeqpCsv(dir + "/known/results.csv");
  EXPECT_EQ(status[kB], "ExpectedFail");
  EXPECT_EQ(status[kA], "Pass");
  EXPECT_EQ(slurp(dir + "/known/failures.csv").find(kB), std::string::npos)
      << "an expected failure is not new";

  // A new failure beside it (the fault in kB and kC, not kA): exit 1, re-run
  // once (it fails again), in failures.csv.
  ASSERT_EQ(sh(run + " --plant-fault shift-t --plant-fault-in '[ac]*' --out " + dir + "/new",
               dir + "/new.txt"),
            1)
      << slurp(dir + "/new.txt");
  status = readDeqpCsv(dir + "/new/results.csv");
  EXPECT_EQ(status[kB], "ExpectedFail");
  EXPECT_EQ(status[kC], "Fail");
  EXPECT_TRUE(fs::exists(dir + "/new/" + kC + "/rerun/device/results.json"))
      << "the new failure was not re-run";
  EXPECT_FALSE(fs::exists(dir + "/new/" + kB + "/rerun")) << "an expected failure is not re-run";
  const std::string failures = slurp(dir + "/new/failures.csv");
  EXPECT_NE(failures.find(kC + ",Fail"), std::string::npos) << failures;
  EXPECT_EQ(failures.find(kB + ","), std::string::npos) << failures;
  EXPECT_NE(failures.find("again"), std::string::npos) << failures;

  // The bug fixed: an unexpected pass, exit 1, listed to be removed.
  ASSERT_EQ(sh(run + " --out " + dir + "/fixed", dir + "/fixed.txt"), 1)
      << slurp(dir + "/fixed.txt");
  EXPECT_EQ(readDeqpCsv(dir + "/fixed/results.csv")[kB], "UnexpectedImprovement(Pass)");
  EXPECT_NE(slurp(dir + "/fixed.txt").find("UNEXPECTED PASS"), std::string::npos)
      << slurp(dir + "/fixed.txt");
  EXPECT_NE(slurp(dir + "/fixed/failures.csv").find(kB + ",Pass"), std::string::npos);
  const nlohmann::json summary = nlohmann::json::parse(slurp(dir + "/fixed/summary.json"));
  EXPECT_EQ(summary["fails_run"], nlohmann::json::array({kB}));
}

// A failure that does not repeat is a flake: reported, not failing; a case
// the flakes file names does not fail; a case the skips file names never runs.
TEST(Gate, FlakesAndSkips) {
  const std::string dir = fresh("gate-flakes");
  const std::string baseline = write(dir + "/driver.csv", "# nothing known\n");
  const std::string run = kBin + " run --no-validation" + kThree + " --baseline " + baseline;

  // A process per case: a crash in a reused worker would run again alone
  // first (and pass there: "crashes only in a reused process").
  ASSERT_EQ(sh(run + " --process-per-case --plant-fault crash-once --plant-fault-in " + kC +
                   " --out " + dir + "/once",
               dir + "/once.txt"),
            0)
      << slurp(dir + "/once.txt");
  EXPECT_EQ(readDeqpCsv(dir + "/once/results.csv")[kC], "Flake");
  EXPECT_NE(slurp(dir + "/once.txt").find("FLAKE"), std::string::npos) << slurp(dir + "/once.txt");
  EXPECT_NE(slurp(dir + "/once/failures.csv").find(kC + ",Crash"), std::string::npos);

  // The same fault every time is no flake: it fails (the planted fault proves the re-run can fail).
  ASSERT_EQ(sh(run + " --plant-fault crash --plant-fault-in " + kC + " --out " + dir + "/always",
               dir + "/always.txt"),
            1)
      << slurp(dir + "/always.txt");
  EXPECT_EQ(readDeqpCsv(dir + "/always/results.csv")[kC], "Crash");

  // Named as a flake (the file beside the baseline), the crash does not fail the run.
  write(dir + "/driver-flakes.txt", "^culling/cull-op  # crashes now and then\n");
  write(dir + "/driver-skips.txt", "^results/\n");
  ASSERT_EQ(sh(run + " --plant-fault crash --plant-fault-in " + kC + " --out " + dir + "/known",
               dir + "/known.txt"),
            0)
      << slurp(dir + "/known.txt");
  const auto status = readDeqpCsv(dir + "/known/results.csv");
  EXPECT_EQ(status.at(kC), "KnownFlake");
  EXPECT_EQ(status.at(kA), "Skip");
  EXPECT_FALSE(fs::exists(dir + "/known/" + kA)) << "a skipped case ran";
  EXPECT_NE(slurp(dir + "/known.txt").find("Skips: " + dir + "/driver-skips.txt (1 patterns)"),
            std::string::npos)
      << slurp(dir + "/known.txt");
  // A skipped case is NotSupported, never a pass.
  const nlohmann::json summary = nlohmann::json::parse(slurp(dir + "/known/summary.json"));
  EXPECT_EQ(summary["cases"][0]["status"], "NotSupported");
  EXPECT_EQ(summary["counts"]["Pass"], 1);
}

// Issue 56: a skips or flakes file of patterns that each compile large
// (60,000 of x[a-z]{1000}, 780 KB: 3.1 GB before) is refused at the line
// that passes the bound on their compiled size: exit 2 naming the file and
// the line, whether --skips names it, it lies beside --baseline, or merge
// --skips names it; no case runs.
TEST(Gate, PatternsThatCompileLargeAreExit2AtTheLine) {
  const std::string dir = fresh("gate-large-patterns");
  std::string text = "# each compiles to about a thousand instructions\n";
  for (int i = 0; i < 60000; ++i) text += "x[a-z]{1000}\n";
  const std::string skips = write(dir + "/large-skips.txt", text);
  fs::create_directories(dir + "/skips-beside");
  fs::create_directories(dir + "/flakes-beside");
  fs::create_directories(dir + "/shard");
  const std::string beside = write(dir + "/skips-beside/driver.csv", "# nothing known\n");
  const std::string flakes_beside = write(dir + "/flakes-beside/driver.csv", "# nothing known\n");
  write(dir + "/skips-beside/driver-skips.txt", text);
  write(dir + "/flakes-beside/driver-flakes.txt", text);
  auto refused = [&](const std::string& name, const std::string& command, const std::string& file) {
    const std::string log = dir + "/" + name + ".txt";
    EXPECT_EQ(sh(command, log), 2) << name << "\n" << slurp(log);
    const std::string said = slurp(log);
    const size_t at = said.find(file + ":");
    ASSERT_NE(at, std::string::npos) << name << "\n" << said;
    const int line = std::atoi(said.c_str() + at + file.size() + 1);
    EXPECT_GT(line, 2) << said;
    EXPECT_LT(line, 400) << said;
    EXPECT_NE(said.find("the patterns up to this one compile to"), std::string::npos) << said;
  };
  const std::string run = kBin + " run --no-validation" + caseArg(kA);
  refused("run", run + " --skips " + skips + " --out " + dir + "/run", skips);
  EXPECT_FALSE(fs::exists(dir + "/run/" + kA)) << "a case ran";
  refused("beside", run + " --baseline " + beside + " --out " + dir + "/beside",
          dir + "/skips-beside/driver-skips.txt");
  refused("flakes", run + " --baseline " + flakes_beside + " --out " + dir + "/flakes",
          dir + "/flakes-beside/driver-flakes.txt");
  refused("merge", kBin + " merge " + dir + "/shard --skips " + skips + " --out " + dir + "/merged",
          skips);
}

// Shards of one run, by --shard and by GoogleTest's variables, merged back
// into the run they make together.
TEST(Shards, ShardsMergeIntoTheWholeRun) {
  const std::string dir = fresh("shards");
  const std::string run = kBin + " run --no-validation" + kThree;
  ASSERT_EQ(sh(run + " --shard 1/2 --out " + dir + "/s1", dir + "/s1.txt"), 0)
      << slurp(dir + "/s1.txt");
  const std::string status_file = dir + "/shard-status";
  ASSERT_EQ(sh("GTEST_TOTAL_SHARDS=2 GTEST_SHARD_INDEX=1 GTEST_SHARD_STATUS_FILE=" + status_file +
                   " " + run + " --out " + dir + "/s2",
               dir + "/s2.txt"),
            0)
      << slurp(dir + "/s2.txt");
  EXPECT_TRUE(fs::exists(status_file));
  const auto s1 = readDeqpCsv(dir + "/s1/results.csv"), s2 = readDeqpCsv(dir + "/s2/results.csv");
  EXPECT_EQ(s1.size(), 2u);
  EXPECT_EQ(s2.size(), 1u);
  for (const auto& [name, status] : s1)
    EXPECT_EQ(s2.count(name), 0u) << name << " is in both shards";

  ASSERT_EQ(
      sh(kBin + " merge " + dir + "/s1 " + dir + "/s2 --out " + dir + "/all", dir + "/merge.txt"),
      0)
      << slurp(dir + "/merge.txt");
  const auto all = readDeqpCsv(dir + "/all/results.csv");
  EXPECT_EQ(all.size(), 3u);
  for (const std::string& c : {kA, kB, kC}) EXPECT_EQ(all.count(c), 1u) << c;
  EXPECT_TRUE(fs::exists(dir + "/all/" + kC + "/device/results.json"));
  const nlohmann::json summary = nlohmann::json::parse(slurp(dir + "/all/summary.json"));
  EXPECT_EQ(summary["planned_cases"], 3);
  EXPECT_FALSE(summary["interrupted"].get<bool>());

  // A shard twice is refused, naming the case.
  EXPECT_EQ(
      sh(kBin + " merge " + dir + "/s1 " + dir + "/s1 --out " + dir + "/twice", dir + "/twice.txt"),
      2);
  EXPECT_NE(slurp(dir + "/twice.txt").find("is in both"), std::string::npos)
      << slurp(dir + "/twice.txt");
  EXPECT_EQ(sh(run + " --shard 4/3 --out " + dir + "/bad", dir + "/bad.txt"), 2);
  EXPECT_NE(slurp(dir + "/bad.txt").find("I/N"), std::string::npos) << slurp(dir + "/bad.txt");
}

// The README's CI matrix recipe ("Over several machines"): each job a shard
// by GitLab's variables into shard-$CI_NODE_INDEX, then `rayspec merge shard-*` into one report.
TEST(Shards, GitLabMatrixRecipeMergesIntoTheWholeRun) {
  const std::string dir = fresh("gitlab-matrix");
  const std::string run = kBin + " run --no-validation" + kThree;
  for (int node = 1; node <= 2; ++node) {
    const std::string n = std::to_string(node);
    // The job's environment, as GitLab sets it.
    ASSERT_EQ(sh("cd " + dir +
                     " && unset GTEST_TOTAL_SHARDS GTEST_SHARD_INDEX && export CI_NODE_TOTAL=2 "
                     "CI_NODE_INDEX=" +
                     n + " && " + run + " --out shard-$CI_NODE_INDEX",
                 dir + "/node" + n + ".txt"),
              0)
        << slurp(dir + "/node" + n + ".txt");
    EXPECT_NE(slurp(dir + "/node" + n + ".txt").find("Shard: shard " + n + " of 2"),
              std::string::npos)
        << slurp(dir + "/node" + n + ".txt");
  }
  ASSERT_EQ(sh("cd " + dir + " && " + kBin + " merge shard-* --out all", dir + "/merge.txt"), 0)
      << slurp(dir + "/merge.txt");
  const auto all = readDeqpCsv(dir + "/all/results.csv");
  EXPECT_EQ(all.size(), 3u);
  for (const std::string& c : {kA, kB, kC}) EXPECT_EQ(all.count(c), 1u) << c;
}

}  // namespace
