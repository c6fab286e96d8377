// A saved case judged anew from its bundles (run/saved_case.h), by the case
// as the run's variant made it (run/case_as_run.h): the verdict is what the
// bundles show, whatever a summary said of them.
#include <gtest/gtest.h>

#include <filesystem>

#include "bundle/results_io.h"
#include "metamorphic/motion_spec.h"
#include "model/model_engine.h"
#include "parse/parse_case.h"
#include "result_support.h"
#include "run/case_as_run.h"
#include "run/model_adapter.h"
#include "run/saved_case.h"
#include "suite_cases.h"
#include "temp_dir.h"

namespace rayspec {
namespace {
namespace fs = std::filesystem;

const std::string kJudgedCase = "results/miss-xor-closest-hit";

// The index of the one case these tests judge.
CaseIndex judgedCaseIndex() {
  CaseIndex index{kSuiteCases, {}};
  index.by_name.emplace(kJudgedCase,
                        CaseFile{kSuiteCases + "/" + kJudgedCase + ".yaml", kJudgedCase});
  return index;
}

// A case folder as a run leaves it: the model's bundle, and the same
// answer as the device's (a device that agrees with the model), unless
// `device` is false.
std::string savedCaseFolder(const std::string& name, bool device) {
  const std::string folder = freshTempDir("rayspec-saved-case/" + name);
  const Case c = suiteCaseFile(kJudgedCase);
  const Plan plan = derivePlan(c);
  Results r = *ModelAdapter(ModelOptions{}).run(c, plan);
  r.case_name = c.name;
  r.case_hash = c.source_hash;
  EXPECT_TRUE(writeResults(r, folder + "/model", {}).ok());
  r.backend = "vulkan";
  r.device = "saved device";
  if (device) {
    EXPECT_TRUE(writeResults(r, folder + "/device", {}).ok());
  }
  return folder;
}

Results readBack(const std::string& dir) {
  std::string error;
  Results r = orError(readResults(dir), &error);
  EXPECT_EQ(error, "");
  return r;
}

TEST(VariantOptions, ReadBackWhatRunVariantWrites) {
  RunOptions opt;
  opt.through = FeaturePath::Update;
  opt.permute = 7;
  opt.move = RigidMotion{};
  opt.move->sign = {-1, 1, 1};
  opt.move->axis = {1, 0, 2};
  const std::string written = runVariant(opt);
  RunOptions back;
  ASSERT_TRUE(variantOptions(written, back).ok()) << written;
  EXPECT_EQ(runVariant(back), written);
  EXPECT_EQ(*back.permute, 7u);
  ASSERT_TRUE(variantOptions("", back).ok());
  EXPECT_FALSE(back.through || back.permute || back.move);
  for (const std::string bad :
       {"permute -1", "permute 1.5", "permute", "permute 7; permute 7", "teleport 3",
        "permute 7; through update", "through nowhere", "move q,x,z", "permute 7;"}) {
    RunOptions o;
    EXPECT_FALSE(variantOptions(bad, o).ok()) << bad;
  }
}

TEST(CaseAsRun, APermutedCaseHasTheHashItsRunRecorded) {
  const Case c = suiteCaseFile(kJudgedCase);
  RunOptions opt;
  opt.permute = 3;
  const CaseAsRun permuted = caseAsRun(c, opt);
  ASSERT_TRUE(permuted.runs);
  EXPECT_NE(permuted.runs->source_hash, c.source_hash);
  RunOptions none;
  EXPECT_EQ(caseAsRun(c, none).runs->source_hash, c.source_hash);
}

// A case --permute moves nothing in is not run under --permute alone (its
// run would repeat the plain run), saying so; with --move it runs.
TEST(CaseAsRun, ACaseNothingToPermuteInIsNotRunUnderPermuteAlone) {
  const ParseResult p = parseCaseText(R"(rules: [R-ORDER-UNSPEC]
scene:
  blas:
    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]
  instances: [{blas: t}]
rays:
  list: [{origin: [0.2, 0.2, 1], direction: [0, 0, -1]}]
pipeline:
  hit_groups: [{closest_hit: [record: [primitive_id]]}]
outputs:
  per_ray: [primitive_id]
)",
                                      "one.yaml", "one");
  ASSERT_TRUE(p.value);
  RunOptions opt;
  opt.permute = 3;
  const CaseAsRun alone = caseAsRun(*p.value, opt);
  ASSERT_TRUE(alone.not_run);
  EXPECT_FALSE(alone.runs);
  EXPECT_EQ(alone.not_run->status, Status::NotSupported);
  EXPECT_NE(alone.not_run->headline.find("moves nothing"), std::string::npos)
      << alone.not_run->headline;
  opt.move = *parseMotionSpec("-y,x,z");
  EXPECT_TRUE(caseAsRun(*p.value, opt).runs);
}

TEST(SavedCase, TheVerdictIsWhatTheBundlesShow) {
  const CaseIndex index = judgedCaseIndex();
  const std::string folder = savedCaseFolder("agree", true);
  std::string error;
  const std::optional<CaseOutcome> pass =
      orError(judgeSavedCase(folder, kJudgedCase, RunOptions{}, index), &error);
  ASSERT_EQ(error, "");
  ASSERT_TRUE(pass);
  EXPECT_EQ(pass->status, Status::Pass) << pass->headline;
  EXPECT_EQ(pass->device_name, "saved device");
  // The device's records differ from the model's: a Fail, whatever else says Pass.
  Results device = readBack(folder + "/device");
  for (uint32_t& w : device.records) w ^= 0x5a5a5a5au;
  ASSERT_TRUE(writeResults(device, folder + "/device", {}).ok());
  const std::optional<CaseOutcome> fail =
      orError(judgeSavedCase(folder, kJudgedCase, RunOptions{}, index), &error);
  ASSERT_TRUE(fail);
  EXPECT_EQ(fail->status, Status::Fail) << fail->headline;
  // A validation error the device reported fails the case too.
  device = readBack(folder + "/model");
  device.device = "saved device";
  device.validation_messages = {"VUID-vkCmdTraceRaysKHR-None-08606: forged away"};
  ASSERT_TRUE(writeResults(device, folder + "/device", {}).ok());
  const std::optional<CaseOutcome> invalid =
      orError(judgeSavedCase(folder, kJudgedCase, RunOptions{}, index), &error);
  ASSERT_TRUE(invalid);
  EXPECT_EQ(invalid->status, Status::Fail) << invalid->headline;
  EXPECT_NE(invalid->headline.find("VUID-vkCmdTraceRaysKHR-None-08606"), std::string::npos)
      << invalid->headline;
}

TEST(SavedCase, OneSideIsNeverAPassAndNoneIsNoVerdict) {
  const CaseIndex index = judgedCaseIndex();
  const std::string model_only = savedCaseFolder("model-only", false);
  std::string error;
  const std::optional<CaseOutcome> one =
      orError(judgeSavedCase(model_only, kJudgedCase, RunOptions{}, index), &error);
  ASSERT_TRUE(one) << error;
  EXPECT_EQ(one->status, Status::NotSupported) << one->headline;
  const std::string empty = freshTempDir("rayspec-saved-case/none");
  const std::optional<CaseOutcome> none =
      orError(judgeSavedCase(empty, kJudgedCase, RunOptions{}, index), &error);
  EXPECT_EQ(error, "");
  EXPECT_FALSE(none);
}

// Bundles of a case changed since, of a variant other than the run's, or of
// a case not here cannot be judged: the error says why.
TEST(SavedCase, BundlesOfAnotherCaseCannotBeJudged) {
  const CaseIndex index = judgedCaseIndex();
  const std::string folder = savedCaseFolder("other", true);
  RunOptions permuted;
  permuted.permute = 3;
  const Result<std::optional<CaseOutcome>> hash =
      judgeSavedCase(folder, kJudgedCase, permuted, index);
  ASSERT_FALSE(hash);
  EXPECT_EQ(hash.error().kind, ErrorKind::Harness);
  EXPECT_NE(hash.error().message.find("case_hash"), std::string::npos) << hash.error().message;
  const Result<std::optional<CaseOutcome>> elsewhere =
      judgeSavedCase(folder, "results/not-here", RunOptions{}, index);
  ASSERT_FALSE(elsewhere);
  EXPECT_NE(elsewhere.error().message.find("no case results/not-here under"), std::string::npos)
      << elsewhere.error().message;
}

}  // namespace
}  // namespace rayspec
