// `rayspec reduce` end to end on the device: a suite case broken by a
// planted fault, reduced; the reduced case must still fail with the fault,
// pass without it, and be smaller. Exit 1 for a case that does not fail, 2
// for a file that is not there.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>
#include <vector>

#include "cli_helpers.h"

namespace {

using cli::kBin;
using cli::sh;
using cli::slurp;

const char* const kCase = "inactive/before-active-mask-zero-instance/one-first";
const char* const kFault = "instance-mask-ignored";

TEST(Reduce, ReducedCaseFailsWithTheFaultAndPassesWithout) {
  const std::string dir = cli::fresh("reduce-mask");
  const std::string log = dir + "/reduce.log";
  ASSERT_EQ(
      sh(kBin + " reduce " + kCase + " --plant-fault " + kFault + " --out " + dir + "/out", log), 0)
      << slurp(log);
  const std::string reduced = dir + "/out/reduced.yaml";
  ASSERT_TRUE(std::filesystem::exists(reduced)) << slurp(log);
  const std::string report = slurp(dir + "/out/report.md");
  EXPECT_NE(report.find("rayspec run --case"), std::string::npos);
  EXPECT_NE(report.find("R-MASK: instance mask"), std::string::npos);  // the rule's text
  EXPECT_NE(slurp(dir + "/out/steps.txt").find("-> kept"), std::string::npos);
  // A case mutation is made in rayspec's results, not in what a device is
  // given: no repro.c, and the report says why first.
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/repro.c"));
  EXPECT_LT(report.find("No repro.c: the planted fault instance-mask-ignored is made in the model "
                        "run on the case"),
            report.find("## Reproduce"))
      << report;
  // Smaller: the six rays and six instances of the original went.
  std::smatch m;
  const std::string out = slurp(log);
  ASSERT_TRUE(std::regex_search(out, m, std::regex("rays 6 -> (\\d+), instances 6 -> (\\d+)")))
      << out;
  EXPECT_LT(std::stoi(m[1]), 6);
  EXPECT_LT(std::stoi(m[2]), 6);
  EXPECT_EQ(sh(kBin + " run --case " + reduced + " --plant-fault " + kFault + " --out " + dir +
                   "/with-fault",
               dir + "/with.log"),
            1)
      << slurp(dir + "/with.log");
  EXPECT_EQ(sh(kBin + " run --case " + reduced + " --out " + dir + "/without-fault",
               dir + "/without.log"),
            0)
      << slurp(dir + "/without.log");
}

// --device-command: each variant's device side run by a command (here this
// build's own device-only run with the layout fault offsets-ignored, standing
// in for another driver such as tools/second-driver.sh device), judged here.
const std::string kDeviceOnly = kBin +
                                " run --no-model --cases \"$RAYSPEC_VARIANT_CASES\" --filter "
                                "\"$RAYSPEC_VARIANT_NAME\" --out \"$RAYSPEC_VARIANT_OUT\" "
                                "--plant-fault offsets-ignored";

TEST(Reduce, ADeviceCommandRunsEachVariantsDeviceSide) {
  const std::string dir = cli::fresh("reduce-command");
  const std::string log = dir + "/reduce.log";
  ASSERT_EQ(sh(kBin + " reduce accel/layouts-triangles --device-command '" + kDeviceOnly +
                   "' --out " + dir + "/out",
               log),
            0)
      << slurp(log);
  const std::string out = slurp(log);
  EXPECT_NE(out.find("Reduced accel/layouts-triangles"), std::string::npos) << out;
  const std::string report = slurp(dir + "/out/report.md");
  EXPECT_NE(report.find("--device-results"), std::string::npos) << report;
  // The device the command's runs said they ran on, and the command.
  EXPECT_NE(report.find("llvmpipe"), std::string::npos) << report;
  EXPECT_NE(report.find(", run by `"), std::string::npos) << report;
  // Every variant's device side ran through the command, none here.
  EXPECT_TRUE(std::filesystem::exists(dir + "/out/runs/variant-1/device"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/out/cases/accel/layouts-triangles.yaml"));
}

// repro.c, built (C99, warnings as errors) and run on lavapipe; its exit status.
int buildAndPlay(const std::string& file, const std::string& dir) {
  const std::string build = std::string(RAYSPEC_C_COMPILER) +
                            " -std=c99 -Wall -Wextra -Wno-missing-field-initializers -Werror " +
                            file + " -lvulkan -o " + dir + "/repro";
  if (sh(build, dir + "/build.txt") != 0) {
    ADD_FAILURE() << file << " does not build:\n" << slurp(dir + "/build.txt");
    return -1;
  }
  return sh(dir + "/repro llvmpipe", dir + "/play.txt");
}

// The reduced case as a standalone C file (export/export_c.h): a reduction
// under a planted layout fault leaves a repro.c whose builds misread their
// inputs as the fault does, so it FAILs on lavapipe, and report.md leads
// with its build line; the same case exported without the fault PASSes.
TEST(Reduce, TheReproducerCarriesALayoutFaultAndFailsOnLavapipe) {
  const std::string dir = cli::fresh("reduce-repro");
  // accel/layouts-triangles' indexed quad behind junk (small: the
  // reduction tries a few variants).
  const std::string input = dir + "/offsets.yaml";
  std::ofstream(input) << R"(rules: [R-BUILTIN]
scene:
  build: {data_offsets: true, vertex_stride: 24}
  blas:
    quad:
      - triangles:
          vertices: [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
          indices: [0, 1, 2, 0, 2, 3]
          index_type: uint16
  instances: [{blas: quad, custom_index: 10}]
rays:
  list:
    - {origin: [0.5, -0.5, 1], direction: [0, 0, -1]}
    - {origin: [-0.5, 0.5, 1], direction: [0, 0, -1]}
pipeline:
  miss: [[record: {hit: 0}]]
  hit_groups:
    - closest_hit: [record: [hit, instance_custom_index, primitive_id]]
outputs:
  per_ray: [hit, instance_custom_index, primitive_id]
)";
  const std::string log = dir + "/reduce.log";
  ASSERT_EQ(
      sh(kBin + " reduce " + input + " --plant-fault offsets-ignored --out " + dir + "/out", log),
      0)
      << slurp(log);
  const std::string report = slurp(dir + "/out/report.md");
  EXPECT_LT(report.find("cc repro.c -lvulkan -o repro\n./repro [DEVICE]"),
            report.find("## Reproduce"))
      << report;
  EXPECT_NE(report.find("It carries the planted fault offsets-ignored"), std::string::npos)
      << report;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/repro.amber"));
  EXPECT_NE(report.find("No repro.amber: an Amber script cannot carry the planted fault "
                        "offsets-ignored"),
            std::string::npos)
      << report;
  EXPECT_EQ(buildAndPlay(dir + "/out/repro.c", dir), 1) << slurp(dir + "/play.txt");
  EXPECT_NE(slurp(dir + "/play.txt").find("FAIL: "), std::string::npos) << slurp(dir + "/play.txt");
  ASSERT_EQ(sh(kBin + " export " + dir + "/out/reduced.yaml --out " + dir + "/plain",
               dir + "/export.log"),
            0)
      << slurp(dir + "/export.log");
  EXPECT_EQ(buildAndPlay(dir + "/plain/repro.c", dir), 0) << slurp(dir + "/play.txt");
}

// Sizes, numbers and operators: a generated 4 x 4 grid, a 4 x 4 launch and a
// loop of six trips, with a fault that runs every loop one trip more. The
// reduction lowers the grid to one cell, lists one ray, lowers the trip
// count to 0 and takes the `mul` by 1 away; the result still fails with the
// fault and passes without it.
TEST(Reduce, SizesNumbersAndOperatorsGoDown) {
  const std::string dir = cli::fresh("reduce-numbers");
  const std::string input = dir + "/loop.yaml";
  std::ofstream(input) << R"(rules: [R-CONTROL-FLOW]
scene:
  blas:
    grid:
      - triangles: {grid: {cells: [4, 4], size: [2, 2], center: [0, 0, 0]}}
  instances:
    - {blas: grid}
rays:
  grid: {size: [4, 4], origin: [-0.95, -0.9, 5], du: [0.5, 0, 0], dv: [0, 0.5, 0], direction: [0, 0, -1]}
pipeline:
  miss:
    - [count: miss]
  hit_groups:
    - closest_hit:
        - let: {n: 0}
        - repeat: 6
          var: i
          do: [set: {n: {add: [{mul: [var.n, 1]}, 1]}}]
        - record: {value: var.n}
outputs:
  counters: [miss]
  per_ray: [value]
)";
  const std::string log = dir + "/reduce.log";
  ASSERT_EQ(
      sh(kBin + " reduce " + input + " --plant-fault loop-trip-off-by-one --out " + dir + "/out",
         log),
      0)
      << slurp(log);
  EXPECT_NE(slurp(log).find("rays 16 -> 1,"), std::string::npos) << slurp(log);
  const std::string reduced = slurp(dir + "/out/reduced.yaml");
  EXPECT_NE(reduced.find("repeat: 0"), std::string::npos) << reduced;
  EXPECT_EQ(reduced.find("mul:"), std::string::npos) << reduced;
  EXPECT_EQ(reduced.find("cells: [4, 4]"), std::string::npos) << reduced;
  const std::string steps = slurp(dir + "/out/steps.txt");
  EXPECT_NE(steps.find("cells[0] (generator): 4 -> 1"), std::string::npos) << steps;
  EXPECT_NE(steps.find("(operator): its operand 0"), std::string::npos) << steps;
  const std::string run = kBin + " run --case " + dir + "/out/reduced.yaml --out " + dir;
  EXPECT_EQ(sh(run + "/with --plant-fault loop-trip-off-by-one", dir + "/with.log"), 1)
      << slurp(dir + "/with.log");
  EXPECT_EQ(sh(run + "/without", dir + "/without.log"), 0) << slurp(dir + "/without.log");
}

TEST(Reduce, ACaseThatPassesIsNotReduced) {
  const std::string dir = cli::fresh("reduce-pass");
  EXPECT_EQ(sh(kBin + " reduce " + kCase + " --out " + dir + "/out", dir + "/log"), 1)
      << slurp(dir + "/log");
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/reduced.yaml"));
  // The verdict named once (issue 61: it said "Pass: Pass").
  EXPECT_NE(
      slurp(dir + "/log").find(std::string(kCase) + " does not fail to begin with: it passes\n"),
      std::string::npos)
      << slurp(dir + "/log");
}

// A word for the shell this test's command lines go through.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char ch : text) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

// Every file called PWNED under dir.
std::vector<std::string> pwned(const std::string& dir) {
  std::vector<std::string> found;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.path().filename() == "PWNED") found.push_back(e.path().string());
  return found;
}

// Issue 56, item 10: an --out path holding a quote and `$(touch PWNED)`.
// The device command gets the paths in its environment, never in a shell
// line, so nothing runs from the path; the reproduction report.md shows,
// run by sh (with rayspec and sh standing in as functions that list their
// arguments), passes the path as one word and runs nothing from it either.
TEST(Reduce, AQuoteInTheOutPathRunsNothing) {
  const std::string dir = cli::fresh("reduce-quoted"), work = dir + "/work";
  std::filesystem::create_directories(work);
  const std::string out = dir + "/o'$(touch PWNED)x`touch PWNED`";
  const std::string log = dir + "/reduce.log";
  ASSERT_EQ(sh("cd " + quoted(work) + " && " + kBin +
                   " reduce accel/layouts-triangles --max-attempts 3 --device-command " +
                   quoted(kDeviceOnly) + " --out " + quoted(out),
               log),
            0)
      << slurp(log);
  EXPECT_TRUE(std::filesystem::exists(out + "/runs/variant-1/device")) << slurp(log);
  EXPECT_EQ(pwned(dir), std::vector<std::string>{}) << slurp(log);
  // The reproduction, run: every word as given.
  const std::string report = slurp(out + "/report.md");
  const size_t at = report.find("## Reproduce\n\n```\n");
  ASSERT_NE(at, std::string::npos) << report;
  const size_t begin = report.find('\n', report.find("```", at)) + 1;
  const std::string line = report.substr(begin, report.find("\n```", begin) - begin);
  const std::string script = dir + "/reproduce.sh";
  std::ofstream(script) << "rayspec() { printf '%s\\n' \"$@\" > rayspec-args.txt; }\n"
                        << "sh() { printf '%s\\n' \"$@\" > sh-args.txt; }\n"
                        << line << "\n";
  ASSERT_EQ(sh("cd " + quoted(work) + " && /bin/sh " + quoted(script), dir + "/reproduce.log"), 0)
      << line << "\n"
      << slurp(dir + "/reproduce.log");
  EXPECT_EQ(pwned(dir), std::vector<std::string>{}) << line;
  EXPECT_EQ(slurp(work + "/sh-args.txt"), "-c\n" + kDeviceOnly + "\n") << line;
  EXPECT_EQ(slurp(work + "/rayspec-args.txt"),
            "run\n--cases\n" + out + "/cases\n--device-results\n" + out + "/device\n")
      << line;
}

// Issue 56, item 12: a device command that runs past --timeout is killed
// with its process group (the sleep it left in the background too), and
// the reduction ends: exit 2 naming the command, the timeout and the log.
TEST(Reduce, ADeviceCommandPastTheTimeoutIsKilledWithItsGroup) {
  const std::string dir = cli::fresh("reduce-command-timeout");
  const std::string pid_file = dir + "/sleeper.pid";
  const std::string command = "sleep 300 & echo $! > " + pid_file + "; wait";
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(sh(kBin + " reduce accel/layouts-triangles --timeout 2 --device-command " +
                   quoted(command) + " --out " + dir + "/out",
               dir + "/log"),
            2)
      << slurp(dir + "/log");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(60));
  const std::string out = slurp(dir + "/log");
  EXPECT_NE(out.find("the device command `" + command + "` ran longer than --timeout 2 s"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find(dir + "/out/runs/variant-1/command.log"), std::string::npos) << out;
  std::ifstream in(pid_file);
  int pid = 0;
  ASSERT_TRUE(in >> pid) << "the command did not start its sleep";
  // Gone, or a zombie no one has reaped yet: not running.
  std::string stat = slurp("/proc/" + std::to_string(pid) + "/stat");
  for (int i = 0; i < 50 && !stat.empty() && stat.find(") Z") == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    stat = slurp("/proc/" + std::to_string(pid) + "/stat");
  }
  EXPECT_TRUE(stat.empty() || stat.find(") Z") != std::string::npos) << stat;
}

// Issue 56, item 12: a device command that exits 3 and writes nothing is no
// case that does not fail: exit 2 naming the command, its status and its
// log, which holds what it said.
TEST(Reduce, ADeviceCommandThatFailsLeavingNothingIsExit2) {
  const std::string dir = cli::fresh("reduce-command-fails");
  const std::string command = "echo nothing here; exit 3";
  EXPECT_EQ(sh(kBin + " reduce accel/layouts-triangles --device-command " + quoted(command) +
                   " --out " + dir + "/out",
               dir + "/log"),
            2)
      << slurp(dir + "/log");
  const std::string out = slurp(dir + "/log"),
                    command_log = dir + "/out/runs/variant-1/command.log";
  EXPECT_NE(out.find("the device command `" + command +
                     "` exited with status 3 and left no results (its log: " + command_log + ")"),
            std::string::npos)
      << out;
  EXPECT_EQ(slurp(command_log), "nothing here\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/reduced.yaml"));
}

TEST(Reduce, AMissingFileIsBadInputNamingIt) {
  const std::string dir = cli::fresh("reduce-missing");
  EXPECT_EQ(sh(kBin + " reduce " + dir + "/no-such-case.yaml --out " + dir + "/out", dir + "/log"),
            2);
  EXPECT_NE(slurp(dir + "/log").find("no-such-case.yaml"), std::string::npos);
}

}  // namespace
