// `rayspec reduce` end to end on the device: a suite case broken by a
// planted fault, reduced; the reduced case must still fail with the fault,
// pass without it, and be smaller. Exit 1 for a case that does not fail, 2
// for a file that is not there.
#include <fstream>
#include <regex>

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
TEST(Reduce, ADeviceCommandRunsEachVariantsDeviceSide) {
  const std::string dir = cli::fresh("reduce-command");
  const std::string log = dir + "/reduce.log";
  const std::string command = kBin +
                              " run --no-model --cases \"$RAYSPEC_VARIANT_CASES\" --filter "
                              "\"$RAYSPEC_VARIANT_NAME\" --out \"$RAYSPEC_VARIANT_OUT\" "
                              "--plant-fault offsets-ignored";
  ASSERT_EQ(sh(kBin + " reduce accel/layouts-triangles --device-command '" + command + "' --out " +
                   dir + "/out",
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
}

TEST(Reduce, AMissingFileIsBadInputNamingIt) {
  const std::string dir = cli::fresh("reduce-missing");
  EXPECT_EQ(sh(kBin + " reduce " + dir + "/no-such-case.yaml --out " + dir + "/out", dir + "/log"),
            2);
  EXPECT_NE(slurp(dir + "/log").find("no-such-case.yaml"), std::string::npos);
}

}  // namespace
