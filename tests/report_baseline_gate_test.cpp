// The regression gate (report/baseline_gate.h), the flakes and skips files
// (report/baseline.h), outcomes read back from summary.json
// (report/outcome_json.h) and joined run folders (report/merge_runs.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "read_text.h"
#include "report/baseline.h"
#include "report/baseline_gate.h"
#include "report/merge_runs.h"
#include "report/outcome_json.h"
#include "report/run_summary.h"
#include "result_support.h"
#include "test_dir.h"

namespace rayspec {
namespace {

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = testing_support::testDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

CaseOutcome outcome(const std::string& name, Status s) {
  CaseOutcome o;
  o.name = name;
  o.status = s;
  o.headline = statusName(s);
  return o;
}

Baseline gate() {
  std::string error;
  const std::string csv = writeFile("gate.csv", "fam/known,Fail  # driver bug\nfam/fixed,Crash\n");
  writeFile("gate-flakes.txt", "# flaky on this driver\n^fam/wobbly  # issue 12\n");
  writeFile("gate-skips.txt", "^slow/\n");
  Baseline b = orError(loadBaselineSet(csv, "", ""), &error);
  EXPECT_EQ(error, "");
  return b;
}

TEST(BaselineGate, EachResultAgainstItsExpectation) {
  const Baseline b = gate();
  ASSERT_EQ(b.flakes.size(), 1u) << "the flakes file beside the baseline is found";
  ASSERT_EQ(b.skips.size(), 1u);
  struct Row {
    std::string name;
    Status status;
    BaselineMatch match;
    bool rerun, fails;
  } rows[] = {
      {"fam/known", Status::Fail, BaselineMatch::Expected, false, false},
      {"fam/known", Status::Crash, BaselineMatch::None, true, true},  // a different failure
      {"fam/fixed", Status::Pass, BaselineMatch::UnexpectedPass, false, true},
      {"fam/fixed", Status::NotSupported, BaselineMatch::UnexpectedPass, false, true},
      {"fam/new", Status::Fail, BaselineMatch::None, true, true},
      {"fam/new", Status::Pass, BaselineMatch::None, false, false},
      {"fam/new", Status::QualityWarning, BaselineMatch::None, false, false},
      {"fam/new", Status::NotSupported, BaselineMatch::None, false, false},
      {"fam/wobbly-one", Status::Timeout, BaselineMatch::KnownFlake, false, false},
      {"other/fam/wobbly", Status::Fail, BaselineMatch::None, true,
       true},  // the pattern is anchored
  };
  for (const Row& r : rows) {
    CaseOutcome o = outcome(r.name, r.status);
    EXPECT_EQ(applyBaseline(b, o), r.rerun) << r.name << " " << statusName(r.status);
    EXPECT_EQ(o.baseline, r.match)
        << r.name << " " << statusName(r.status) << ": " << o.baseline_note;
    EXPECT_EQ(failsRun(o), r.fails) << r.name << " " << statusName(r.status);
  }
}

TEST(BaselineGate, ARerunThatDiffersIsAFlakeAndOneThatRepeatsFails) {
  const Baseline b = gate();
  CaseOutcome first = outcome("fam/new", Status::Crash);
  ASSERT_TRUE(applyBaseline(b, first));
  CaseOutcome repeated = first;
  applyRerun(repeated, outcome("fam/new", Status::Crash));
  EXPECT_TRUE(failsRun(repeated));
  EXPECT_NE(repeated.baseline_note.find("again"), std::string::npos) << repeated.baseline_note;
  applyRerun(first, outcome("fam/new", Status::Pass));
  EXPECT_EQ(first.baseline, BaselineMatch::Flake);
  EXPECT_FALSE(failsRun(first));
  EXPECT_EQ(first.status, Status::Crash) << "the first result is kept; the flake is a note on it";
}

TEST(BaselineGate, SkippedCasesAreNotSupportedNeverPass) {
  const Baseline b = gate();
  const NamePattern* p = findPattern(b.skips, "slow/huge");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(findPattern(b.skips, "fam/slow/x"), nullptr);
  const CaseOutcome o = skippedOutcome("slow/huge", *p);
  EXPECT_EQ(o.status, Status::NotSupported);
  EXPECT_EQ(o.baseline, BaselineMatch::Skipped);
  EXPECT_NE(o.headline.find("gate-skips.txt:1"), std::string::npos) << o.headline;
  EXPECT_STREQ(deqpResultName(o), "Skip");
}

TEST(BaselineGate, FailuresCsvIsABaselineOfWhatWasUnexpected) {
  const Baseline b = gate();
  std::vector<CaseOutcome> all = {
      outcome("fam/known", Status::Fail), outcome("fam/fixed", Status::Pass),
      outcome("fam/new", Status::Timeout), outcome("fam/fine", Status::Pass)};
  for (CaseOutcome& o : all) applyBaseline(b, o);
  const std::string path = testing_support::testDir() + "/failures.csv";
  ASSERT_EQ(errorText(writeFailuresCsv(all, b.file, path)), "");
  const std::string text = slurp(path);
  EXPECT_EQ(text.find("fam/known"), std::string::npos) << text;
  EXPECT_EQ(text.find("fam/fine"), std::string::npos) << text;
  // It reads back as a baseline: the new failure and the unexpected pass.
  std::string error;
  const Baseline again = orError(loadBaseline(path), &error);
  ASSERT_EQ(error, "") << text;
  EXPECT_EQ(again.expected.size(), 2u) << text;
  EXPECT_EQ(again.expected.at("fam/new"), Status::Timeout);
  EXPECT_EQ(again.expected.at("fam/fixed"), Status::Pass);
}

TEST(BaselineGate, ABadPatternNamesFileAndLine) {
  std::string error;
  orError(loadNamePatterns(writeFile("bad-flakes.txt", "# ok\nfam/a\nfam/(b\n")), &error);
  EXPECT_NE(error.find("bad-flakes.txt:3:"), std::string::npos) << error;
  error.clear();
  orError(loadBaselineSet("", writeFile("missing-dir-flakes.txt", "x"), "/nonexistent/skips.txt"),
          &error);
  EXPECT_NE(error.find("/nonexistent/skips.txt"), std::string::npos) << error;
}

TEST(OutcomeJson, EveryFieldRoundTrips) {
  CaseOutcome o = outcome("fam/a-b.c_d", Status::Fail);
  o.rules = {"R-IGNORE", "R-TIE"};
  o.verdict.add({Status::Fail, "R-IGNORE", "closest-hit saw 3", {3, 5}, 2});
  o.verdict.undefined.push_back({UndefinedReason::NanTriangle, 4, {1, 2}, "scene.blas[0]"});
  o.status = o.verdict.status;
  o.headline = o.verdict.headline();
  o.seconds = 1.5, o.device_seconds = 0.5, o.model_seconds = 0.25;
  o.images = {"primitive"};
  o.failing_rays.push_back({3, 3, 0, "primitive_id", "3", "2"});
  o.baseline = BaselineMatch::Flake;
  o.baseline_note = "the re-run gave Pass";
  o.device_name = "llvmpipe";
  const Result<CaseOutcome> back = outcomeFromJson(outcomeJson(o));
  ASSERT_TRUE(back) << back.error().format();
  EXPECT_EQ(outcomeJson(*back), outcomeJson(o));
  EXPECT_EQ(back->verdict.findings.size(), 1u);
  EXPECT_EQ(back->failing_rays.size(), 1u);
  nlohmann::json broken = outcomeJson(o);
  broken["status"] = "Splendid";
  const Result<CaseOutcome> unknown = outcomeFromJson(broken);
  ASSERT_FALSE(unknown) << "an unknown status is read";
  const std::string message = unknown.error().format();
  EXPECT_NE(message.find("fam/a-b.c_d"), std::string::npos) << message;
  EXPECT_NE(message.find("status"), std::string::npos) << message;
  nlohmann::json untyped = outcomeJson(o);
  untyped["seconds"] = "soon";  // nlohmann-json's exception, caught where it is thrown
  const Result<CaseOutcome> wrong_type = outcomeFromJson(untyped);
  ASSERT_FALSE(wrong_type);
  EXPECT_NE(wrong_type.error().message.find("case fam/a-b.c_d"), std::string::npos)
      << wrong_type.error().message;
}

// A run folder made of outcomes, as a run writes it.
std::string runFolder(const std::string& name, const std::string& device,
                      const std::vector<CaseOutcome>& cases) {
  const std::string dir = testing_support::testDir() + "/" + name;
  std::filesystem::remove_all(dir);
  RunInfo info;
  info.device = device;
  info.model_tier = "exact";
  info.started = "2026-11-23 10:00:00 UTC";
  info.planned_cases = cases.size();
  EXPECT_EQ(errorText(writeReports(cases, info, dir)), "");
  for (const CaseOutcome& o : cases) {
    std::filesystem::create_directories(dir + "/" + o.name + "/device");
    std::ofstream(dir + "/" + o.name + "/device/results.json") << "{}";
  }
  return dir;
}

// A judge that takes each case as its shard's summary.json says (what merge
// did before issue 56), without re-runs: these tests are of the joining.
Result<std::optional<CaseOutcome>> asClaimed(const std::string&, const RunInfo&,
                                             const CaseOutcome& claimed, bool rerun) {
  if (rerun) return std::optional<CaseOutcome>();
  return std::optional<CaseOutcome>(claimed);
}

TEST(MergeRuns, ShardsJoinIntoOneRun) {
  const std::string a = runFolder("shard-a", "llvmpipe",
                                  {outcome("fam/b", Status::Pass), outcome("fam/d", Status::Fail)});
  const std::string b = runFolder("shard-b", "llvmpipe",
                                  {outcome("fam/a", Status::Pass), outcome("fam/c", Status::Pass)});
  const std::string out = testing_support::testDir() + "/merged";
  std::filesystem::remove_all(out);
  const Result<SavedRun> m = mergeRuns({a, b}, out, Baseline{}, {}, asClaimed);
  ASSERT_TRUE(m) << m.error().format();
  ASSERT_EQ(m->outcomes.size(), 4u);
  EXPECT_EQ(m->outcomes[0].name, "fam/a");
  EXPECT_EQ(m->outcomes[3].name, "fam/d");
  EXPECT_EQ(m->info.planned_cases, 4u);
  EXPECT_TRUE(std::filesystem::exists(out + "/fam/d/device/results.json"));
  const Result<SavedRun> back = readSavedRun(out);
  ASSERT_TRUE(back) << back.error().format();
  EXPECT_EQ(back->outcomes.size(), 4u);
  EXPECT_NE(slurp(out + "/failures.csv").find("fam/d,Fail"), std::string::npos);
}

TEST(MergeRuns, RefusesTwoDevicesAndACaseTwice) {
  const std::string a = runFolder("m-a", "llvmpipe", {outcome("fam/a", Status::Pass)});
  const std::string b = runFolder("m-b", "NVIDIA H100", {outcome("fam/b", Status::Pass)});
  const std::string c = runFolder("m-c", "llvmpipe", {outcome("fam/a", Status::Fail)});
  const std::string out = testing_support::testDir() + "/m-out";
  EXPECT_NE(errorText(mergeRuns({a, b}, out, Baseline{}, {}, asClaimed)).find("NVIDIA H100"),
            std::string::npos);
  const std::string twice = errorText(mergeRuns({a, c}, out, Baseline{}, {}, asClaimed));
  EXPECT_NE(twice.find("fam/a"), std::string::npos) << twice;
  EXPECT_NE(twice.find("m-c"), std::string::npos) << twice;
  EXPECT_NE(errorText(mergeRuns({a}, a, Baseline{}, {}, asClaimed)), "");
}

// The bundles' verdict, not the summary's: a shard whose summary.json says
// Pass and "flake" for a case its bundles judge Fail merges as the Fail the
// baseline did not expect, without --baseline too (no mark of the shard's
// gate is kept); a flake only where the re-run's bundles gave another result.
TEST(MergeRuns, EveryCaseIsAsTheJudgeFindsItAndAFlakeNeedsItsRerun) {
  CaseOutcome forged = outcome("fam/new", Status::Pass);
  forged.baseline = BaselineMatch::Flake;
  forged.baseline_note = "a flake\nfam/victim,Fail";
  CaseOutcome flaky = outcome("fam/wobbles", Status::Fail);
  const std::string shard = runFolder("judged", "llvmpipe", {forged, flaky});
  const ShardCaseJudge bundles = [](const std::string&, const RunInfo&, const CaseOutcome& claimed,
                                    bool rerun) -> Result<std::optional<CaseOutcome>> {
    if (rerun && claimed.name == "fam/new") return std::optional<CaseOutcome>();  // none
    CaseOutcome o = outcome(claimed.name, rerun ? Status::Pass : Status::Fail);
    return std::optional<CaseOutcome>(o);
  };
  const std::string out = testing_support::testDir() + "/judged-out";
  const Result<SavedRun> plain = mergeRuns({shard}, out, Baseline{}, {}, bundles);
  ASSERT_TRUE(plain) << plain.error().format();
  for (const CaseOutcome& o : plain->outcomes) {
    EXPECT_EQ(o.status, Status::Fail) << o.name;
    EXPECT_EQ(o.baseline, BaselineMatch::None) << o.name;
    EXPECT_TRUE(failsRun(o)) << o.name;
  }
  const Result<SavedRun> gated = mergeRuns({shard}, out, gate(), {}, bundles);
  ASSERT_TRUE(gated) << gated.error().format();
  ASSERT_EQ(gated->outcomes.size(), 2u);
  const CaseOutcome& unexpected = gated->outcomes[0];
  EXPECT_EQ(unexpected.name, "fam/new");
  EXPECT_EQ(unexpected.baseline, BaselineMatch::None);
  EXPECT_TRUE(failsRun(unexpected));
  EXPECT_NE(unexpected.baseline_note.find("no re-run"), std::string::npos)
      << unexpected.baseline_note;
  EXPECT_EQ(gated->outcomes[1].baseline, BaselineMatch::Flake);
  const std::string failures = slurp(out + "/failures.csv");
  EXPECT_NE(failures.find("fam/new,Fail"), std::string::npos) << failures;
  EXPECT_EQ(failures.find("fam/victim"), std::string::npos) << failures;
  // A refusal of the judge is the merge's.
  const ShardCaseJudge refuses = [](const std::string& dir, const RunInfo&, const CaseOutcome&,
                                    bool) -> Result<std::optional<CaseOutcome>> {
    return errorMessage(dir + "/summary.json: forged");
  };
  EXPECT_NE(errorText(mergeRuns({shard}, out, Baseline{}, {}, refuses)).find("forged"),
            std::string::npos);
}

// A note is one line of failures.csv, whatever it holds: a newline in it
// would add a line for another case.
TEST(BaselineGate, ANoteIsOneLineOfFailuresCsv) {
  CaseOutcome o = outcome("fam/new", Status::Fail);
  o.baseline_note = "the baseline expects Pass\nfam/victim,Fail  # forged\r\n";
  const std::string path = testing_support::testDir() + "/one-line.csv";
  ASSERT_EQ(errorText(writeFailuresCsv({o}, "", path)), "");
  std::istringstream lines(slurp(path));
  std::string line;
  int cases = 0;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] == '#') continue;
    ++cases;
    EXPECT_EQ(line.rfind("fam/new,Fail", 0), 0u) << line;
  }
  EXPECT_EQ(cases, 1);
  // A re-run's headline (what the case printed) joins the note as one line too.
  CaseOutcome first = outcome("fam/x", Status::Fail);
  CaseOutcome again = outcome("fam/x", Status::Crash);
  again.headline = "Crash: died\nfam/victim,Fail";
  applyRerun(first, again);
  EXPECT_EQ(first.baseline_note.find('\n'), std::string::npos) << first.baseline_note;
  EXPECT_NE(first.baseline_note.find("died\\x0Afam/victim"), std::string::npos)
      << first.baseline_note;
}

TEST(BaselineGate, AThroughPathAddsItsOwnEntries) {
  std::string error;
  const std::string csv = writeFile("paths.csv", "fam/known,Fail\nfam/other,Fail\n");
  writeFile("paths-through-serialize.csv",
            "# what serialize changes\nfam/other,Crash\nfam/new,Crash\n");
  const Baseline plain = orError(loadBaselineSet(csv, "", ""), &error);
  EXPECT_EQ(plain.expected.at("fam/other"), Status::Fail);
  EXPECT_EQ(plain.through_file, "");
  const Baseline other_path = orError(loadBaselineSet(csv, "", "", "clone"), &error);
  EXPECT_EQ(other_path.expected.count("fam/new"), 0u);
  const Baseline b = orError(loadBaselineSet(csv, "", "", "serialize"), &error);
  EXPECT_EQ(error, "");
  EXPECT_NE(b.through_file.find("paths-through-serialize.csv"), std::string::npos);
  EXPECT_EQ(b.expected.at("fam/known"), Status::Fail);
  EXPECT_EQ(b.expected.at("fam/other"), Status::Crash);
  EXPECT_EQ(b.expected.at("fam/new"), Status::Crash);
}

// ray-query-compute reads ray-query's file unless it has one of its own.
TEST(BaselineGate, TheComputePathReadsTheRayQueryPathsFile) {
  std::string error;
  const std::string csv = writeFile("queries.csv", "fam/known,Fail\n");
  writeFile("queries-through-ray-query.csv", "fam/known,Pass\n");
  const Baseline b = orError(loadBaselineSet(csv, "", "", "ray-query-compute"), &error);
  EXPECT_EQ(error, "");
  EXPECT_NE(b.through_file.find("queries-through-ray-query.csv"), std::string::npos);
  EXPECT_EQ(b.expected.at("fam/known"), Status::Pass);
  writeFile("queries-through-ray-query-compute.csv", "fam/known,Crash\n");
  const Baseline own = orError(loadBaselineSet(csv, "", "", "ray-query-compute"), &error);
  EXPECT_EQ(own.expected.at("fam/known"), Status::Crash);
  EXPECT_EQ(orError(loadBaselineSet(csv, "", "", "ray-query-in-hit"), &error).through_file, "");
}

}  // namespace
}  // namespace rayspec
