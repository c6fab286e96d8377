// Judging saved device results (run/device_results.h): a SavedDevice reads
// DIR/<case>/device, says NotSupported where the case did not run, refuses a
// bundle of another or a changed case; the options it cannot work with.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "bundle/results_io.h"
#include "metamorphic/permute_case.h"
#include "model/model_engine.h"
#include "parse/parse_case.h"
#include "result_support.h"
#include "results/record_layout.h"
#include "run/device_results.h"
#include "run/fault_seam.h"
#include "run/isolation.h"
#include "run/run_only.h"
#include "suite_cases.h"
#include "temp_dir.h"

namespace rayspec {
namespace {
namespace fs = std::filesystem;

const std::string kCase = "results/miss-xor-closest-hit";

std::string caseText() {
  std::ifstream in(kSuiteCases + "/" + kCase + ".yaml");
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

Case parsed(const std::string& text) {
  const ParseResult p = parseCaseText(text, kSuiteCases + "/" + kCase + ".yaml", kCase);
  EXPECT_TRUE(p.value) << (p.errors.empty() ? "" : p.errors[0].format());
  return p.value ? *p.value : Case{};
}

std::string savedRun(const std::string& name) {
  return freshTempDir("rayspec-device-results/" + name);
}

// A device bundle as a device-only run writes it: the case's hash, its records
// (width x height of them, as the reader checks).
Results save(const std::string& dir, const Case& c, const std::string& bundle_case, uint64_t hash) {
  Results r;
  r.case_name = bundle_case;
  r.backend = "vulkan";
  r.device = "saved device";
  r.width = 2;
  r.height = 1;
  r.case_hash = hash;
  r.records.assign(2 * recordWords(), 7u);
  EXPECT_TRUE(writeResults(r, savedBundleDir(dir, c.name), {}).ok());
  return r;
}

TEST(SavedDevice, ReadsTheCasesBundleAsTheDevicesResults) {
  const Case c = parsed(caseText());
  const std::string dir = savedRun("read");
  const Results saved = save(dir, c, c.name, c.source_hash);
  SavedDevice device(dir);
  EXPECT_EQ(device.name(), "vulkan");
  const Result<Results> read = device.run(c, derivePlan(c));
  ASSERT_TRUE(read) << read.error().format();
  const Results& r = *read;
  EXPECT_TRUE(r.ok()) << r.statusText();
  EXPECT_EQ(r.device, "saved device");
  EXPECT_EQ(r.records, saved.records);
  EXPECT_EQ(savedDevices(dir, {CaseFile{"", c.name}, CaseFile{"", "not/run"}}), "saved device");
}

TEST(SavedDevice, NoBundleIsNotSupportedNeverAPass) {
  const Case c = parsed(caseText());
  const std::string dir = savedRun("none");
  const Result<Results> read = SavedDevice(dir).run(c, derivePlan(c));
  ASSERT_TRUE(read) << read.error().format();
  const Results& r = *read;
  EXPECT_EQ(r.status, SideStatus::NotSupported);
  EXPECT_NE(r.status_detail.find("did not run there"), std::string::npos) << r.status_detail;
  EXPECT_EQ(savedDevices(dir, {CaseFile{"", c.name}}), "");
}

TEST(SavedDevice, BundleOfAChangedCaseIsRefused) {
  const Case c = parsed(caseText());
  const std::string dir = savedRun("changed");
  save(dir, c, c.name, c.source_hash);
  // The same case with one more line (a comment): not the case that ran there.
  const Case edited = parsed(caseText() + "\n# edited since\n");
  EXPECT_NE(edited.source_hash, c.source_hash);
  const Result<Results> read = SavedDevice(dir).run(edited, derivePlan(edited));
  ASSERT_FALSE(read) << "a bundle of a changed case was accepted";
  EXPECT_EQ(read.error().kind, ErrorKind::Harness);
  EXPECT_NE(read.error().message.find("the case changed since it ran there"), std::string::npos)
      << read.error().message;
}

TEST(SavedDevice, BundleOfAnotherCaseOrWithoutHashIsRefused) {
  const Case c = parsed(caseText());
  const std::string other = savedRun("other"), old = savedRun("old");
  save(other, c, "results/another-case", c.source_hash);
  const Result<Results> another = SavedDevice(other).run(c, derivePlan(c));
  ASSERT_FALSE(another);
  EXPECT_EQ(another.error().kind, ErrorKind::Harness);
  save(old, c, c.name, 0);
  const Result<Results> unhashed = SavedDevice(old).run(c, derivePlan(c));
  ASSERT_FALSE(unhashed);
  EXPECT_EQ(unhashed.error().kind, ErrorKind::Harness);
}

// A bundle's counters are those the case keeps: a counter it does not declare
// (mutate would make mutants of it) refuses the bundle, naming the counter.
TEST(SavedDevice, ACounterTheCaseDoesNotKeepRefusesTheBundle) {
  const Case c = parsed(caseText());
  const Plan plan = derivePlan(c);
  ASSERT_FALSE(plan.counters.empty());
  const std::string dir = savedRun("counters");
  Results r = save(dir, c, c.name, c.source_hash);
  for (const std::string& kept : plan.counters) r.counters[kept] = 1;
  ASSERT_TRUE(writeResults(r, savedBundleDir(dir, c.name), {}).ok());
  EXPECT_TRUE(SavedDevice(dir).run(c, plan).ok());
  r.counters["junk"] = 5;
  ASSERT_TRUE(writeResults(r, savedBundleDir(dir, c.name), {}).ok());
  const Result<Results> junk = SavedDevice(dir).run(c, plan);
  ASSERT_FALSE(junk) << "a bundle with an undeclared counter was accepted";
  EXPECT_NE(junk.error().message.find("counter 'junk' is not one the case keeps"),
            std::string::npos)
      << junk.error().message;
}

TEST(SavedDevice, PermutedCaseHasItsOwnHash) {
  const Case c = parsed(caseText());
  const uint64_t seed1 = permuteCase(c, 1).permuted.source_hash;
  EXPECT_NE(seed1, c.source_hash);
  EXPECT_NE(seed1, permuteCase(c, 2).permuted.source_hash);
  EXPECT_EQ(seed1, permuteCase(c, 1).permuted.source_hash);
}

TEST(DeviceResultsOptions, RefusedWhereTheyCannotWork) {
  const std::string dir = savedRun("options");
  RunOptions opt;
  opt.out = savedRun("options-out");
  EXPECT_EQ(errorText(deviceResultsError(opt)), "") << "not asked for";
  opt.device_results = dir;
  EXPECT_EQ(errorText(deviceResultsError(opt)), "");
  RunOptions same = opt;
  same.out = dir + "/.";
  EXPECT_NE(errorText(deviceResultsError(same)).find("is the --out folder"), std::string::npos)
      << errorText(deviceResultsError(same));
  RunOptions missing = opt;
  missing.device_results = dir + "/nothing-here";
  EXPECT_NE(errorText(deviceResultsError(missing)).find("not a folder"), std::string::npos);
  RunOptions no_model = opt;
  no_model.no_model = true;
  EXPECT_NE(errorText(deviceResultsError(no_model)), "");
  RunOptions no_device = opt;
  no_device.no_device = true;
  EXPECT_NE(errorText(deviceResultsError(no_device)), "");
}

// This test program is the full build's: the model is there and the options
// stand as given.
TEST(RunOnly, TheFullBuildKeepsItsModel) {
  ASSERT_TRUE(modelInThisBuild());
  RunOptions opt;
  opt.plant_fault = "shift-t";
  EXPECT_FALSE(optionsForThisBuild(opt).no_model);
  EXPECT_EQ(errorText(plantedFaultError(opt)), "") << "a fault made from the model's results";
}

}  // namespace
}  // namespace rayspec
