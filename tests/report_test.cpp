#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "read_text.h"
#include "report/baseline.h"
#include "report/baseline_gate.h"
#include "report/escape.h"
#include "report/rule_catalog.h"
#include "report/run_summary.h"
#include "report/write_reports.h"
#include "result_support.h"
#include "test_dir.h"

namespace rayspec {
namespace {

std::vector<CaseOutcome> outcomes() {
  std::vector<CaseOutcome> v(3);
  v[0].name = "results/passing";
  v[0].seconds = 0.25;
  v[1].name = "anyhit/failing";
  v[1].verdict.add({Status::Fail, "R-IGNORE", "closest-hit saw <odd> primitives", {3, 5}, 2});
  v[1].status = Status::Fail;
  v[1].headline = v[1].verdict.headline();
  v[1].seconds = 1.5;
  v[1].failing_rays.push_back({3, 3, 0, "primitive_id", "3", "2"});
  v[2].name = "watertight/leaky";
  v[2].status = Status::QualityWarning;
  v[2].seconds = 1e-7;
  return v;
}

// Status and headline follow the verdict's worst finding, derived in one place.
TEST(CaseOutcomeVerdict, StatusAndHeadlineComeFromTheVerdict) {
  CaseOutcome o;
  o.verdict.add({Status::Pass, "R-A", "fine", {}, 0});
  o.deriveFromVerdict();
  EXPECT_EQ(o.status, Status::Pass);
  o.verdict.add({Status::Fail, "R-B", "counter 'miss' differs", {}, 0});
  EXPECT_EQ(o.status, Status::Pass) << "nothing changes until it is derived again";
  o.deriveFromVerdict();
  EXPECT_EQ(o.status, Status::Fail);
  EXPECT_EQ(o.headline, o.verdict.headline());
  EXPECT_NE(o.headline.find("R-B"), std::string::npos) << o.headline;
}

TEST(Reports, ResultsCsvIsDeqpRunnerCsv) {
  const std::string dir = testing_support::testDir() + "/rayspec-report-test";
  ASSERT_EQ(errorText(writeReports(outcomes(), RunInfo{}, dir)), "");
  std::ifstream in(dir + "/results.csv");
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), 3u) << "no header";
  const std::regex deqp(R"(^[^,]+,(Pass|Fail|Warn|Skip|Crash|Timeout),[0-9.eE+-]+$)");
  for (const std::string& l : lines) EXPECT_TRUE(std::regex_match(l, deqp)) << l;
  EXPECT_EQ(lines[1].rfind("anyhit/failing,Fail,", 0), 0u) << lines[1];
  EXPECT_EQ(lines[2].rfind("watertight/leaky,Warn,", 0), 0u) << lines[2];
}

TEST(Reports, InterruptedRunSaysSoInEveryReport) {
  const std::string dir = testing_support::testDir() + "/rayspec-report-interrupted";
  RunInfo info;
  info.planned_cases = 5;
  info.interrupted = true;
  ASSERT_EQ(errorText(writeReports(outcomes(), info, dir)), "");
  const std::string json = slurp(dir + "/summary.json");
  EXPECT_NE(json.find("\"interrupted\": true"), std::string::npos) << json;
  EXPECT_NE(json.find("\"planned_cases\": 5"), std::string::npos) << json;
  EXPECT_EQ(slurp(dir + "/summary.txt").rfind("INTERRUPTED: 3 of 5 planned cases ran\n", 0), 0u);
  EXPECT_NE(slurp(dir + "/report.html").find("INTERRUPTED: 3 of 5 planned cases ran"),
            std::string::npos);

  info.planned_cases = 3;
  info.interrupted = false;
  ASSERT_EQ(errorText(writeReports(outcomes(), info, dir)), "");
  EXPECT_NE(slurp(dir + "/summary.json").find("\"interrupted\": false"), std::string::npos);
  EXPECT_EQ(slurp(dir + "/summary.txt").rfind("complete: 3 of 3 cases\n", 0), 0u);
  EXPECT_EQ(slurp(dir + "/report.html").find("INTERRUPTED"), std::string::npos);
}

TEST(Reports, HtmlPutsFailingCasesFirstEscapesAndCarriesItsSelfCheck) {
  const std::string dir = testing_support::testDir() + "/rayspec-report-test-html";
  ASSERT_EQ(errorText(writeReports(outcomes(), RunInfo{}, dir)), "");
  const std::string html = slurp(dir + "/report.html");
  EXPECT_LT(html.find("id=\"anyhit/failing\""), html.find("id=\"results/passing\""));
  EXPECT_LT(html.find("id=\"watertight/leaky\""), html.find("id=\"results/passing\""));
  EXPECT_NE(html.find("&lt;odd&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<odd>"), std::string::npos);
  EXPECT_NE(html.find("brokenImages"), std::string::npos)
      << "the self-check a headless browser reads";
  EXPECT_NE(html.find("<td>primitive_id</td><td>3</td><td>2</td>"), std::string::npos);
}

// Under a baseline: the gate's line second in summary.txt and at the top of
// report.html, what fails the run listed first and apart from the failures
// the baseline expects, each marked.
TEST(Reports, GateLeadsTheReportsWithUnexpectedResultsFirst) {
  const std::string dir = testing_support::testDir() + "/rayspec-report-test-gate";
  std::vector<CaseOutcome> v = outcomes();
  v[1].baseline = BaselineMatch::Expected;  // anyhit/failing: the baseline lists its Fail
  v[1].baseline_note = "baseline.csv:3";
  CaseOutcome unexpected = v[1];
  unexpected.name = "zz/new-failure";
  unexpected.baseline = BaselineMatch::None;
  unexpected.baseline_note.clear();
  v.push_back(unexpected);
  RunInfo info;
  info.baseline = "references/baselines/x.csv";
  ASSERT_EQ(errorText(writeReports(v, info, dir)), "");
  const std::string text = slurp(dir + "/summary.txt");
  const std::string gate = gateLine(v, info.baseline);
  EXPECT_EQ(gate,
            "Gate (baseline references/baselines/x.csv): FAIL, 1 unexpected failure, 0 "
            "unexpected passes (failures.csv); 1 expected failure, 0 flakes");
  EXPECT_EQ(text.find(gate), text.find('\n') + 1) << text;
  EXPECT_LT(text.find("Failing the run:"), text.find("zz/new-failure:")) << text;
  EXPECT_LT(text.find("zz/new-failure:"), text.find("Other cases:")) << text;
  EXPECT_LT(text.find("Other cases:"), text.find("anyhit/failing:")) << text;
  EXPECT_NE(text.find("[expected]"), std::string::npos) << text;
  const std::string html = slurp(dir + "/report.html");
  EXPECT_NE(html.find("<p id=\"gate\" class=\"Fail\">" + gate), std::string::npos);
  EXPECT_LT(html.find("<p id=\"gate\""), html.find("<h2>Summary"));
  EXPECT_LT(html.find("id=\"zz/new-failure\""), html.find("<h2>Failing as the baseline expects ("));
  EXPECT_LT(html.find("<h2>Failing as the baseline expects ("), html.find("id=\"anyhit/failing\""));

  // Nothing unexpected: PASS; without a baseline, every failure fails the run.
  v.pop_back();
  EXPECT_EQ(gateLine(v, info.baseline),
            "Gate (baseline references/baselines/x.csv): PASS; 1 expected failure, 0 flakes");
  EXPECT_EQ(gateLine(outcomes(), ""),
            "Gate (baseline none: every failing status fails the run): FAIL, 1 unexpected "
            "failure, 0 unexpected passes (failures.csv)")
      << "a QualityWarning does not fail the run";
}

// A probe whose undefined rays the device survived, and a case at fault itself.
std::vector<CaseOutcome> outcomesWithUndefinedBehaviour() {
  std::vector<CaseOutcome> v = outcomes();
  CaseOutcome probe;
  probe.name = "robustness/probe";
  probe.verdict.undefined.push_back(
      {UndefinedReason::RayParameters, 3, {0, 4, 7}, "rays.list[0].tmin: NaN <tmin>"});
  probe.verdict.add({Status::Pass,
                     "R-UB",
                     "R-UB probe: the device survived undefined behaviour: 3 rays",
                     {0, 4, 7},
                     3});
  probe.headline = probe.verdict.headline();
  CaseOutcome broken;
  broken.name = "builtins/broken";
  broken.verdict.undefined.push_back({UndefinedReason::HitRecordOutOfRange,
                                      2,
                                      {5, 6},
                                      "pipeline.raygen[0].trace: hit record 1 of 1"});
  broken.verdict.add(
      {Status::CaseError, "R-UB", "the case has undefined behaviour: 2 rays", {5, 6}, 2});
  broken.status = broken.verdict.status;
  broken.headline = broken.verdict.headline();
  v.insert(v.begin(), broken);
  v.push_back(probe);
  return v;
}

TEST(Reports, CaseErrorIsFailInResultsCsvAndAFailureInJunit) {
  const std::string dir = testing_support::testDir() + "/rayspec-report-test-case-error";
  ASSERT_EQ(errorText(writeReports(outcomesWithUndefinedBehaviour(), RunInfo{}, dir)), "");
  const std::string csv = slurp(dir + "/results.csv");
  EXPECT_NE(csv.find("builtins/broken,Fail,"), std::string::npos) << csv;
  const std::string junit = slurp(dir + "/junit.xml");
  const size_t at = junit.find("name=\"builtins/broken\"");
  ASSERT_NE(at, std::string::npos);
  EXPECT_LT(junit.find("<failure type=\"CaseError\"", at), junit.find("</testcase>", at)) << junit;
  EXPECT_NE(junit.find("failures=\"3\""), std::string::npos)
      << "Fail, QualityWarning and CaseError";
}

TEST(Reports, CaseErrorsAreGroupedApartInHtmlTextAndJson) {
  const std::string dir = testing_support::testDir() + "/rayspec-report-test-case-error-groups";
  ASSERT_EQ(errorText(writeReports(outcomesWithUndefinedBehaviour(), RunInfo{}, dir)), "");
  const std::string html = slurp(dir + "/report.html");
  const size_t failing = html.find("<h2>Failing the run ("),
               errors = html.find("<h2>Case errors ("), others = html.find("<h2>Other cases ("),
               broken = html.find("id=\"builtins/broken\"");
  ASSERT_NE(errors, std::string::npos);
  EXPECT_LT(failing, errors);
  EXPECT_LT(html.find("id=\"anyhit/failing\""), errors) << "device failures first";
  EXPECT_LT(errors, broken);
  EXPECT_LT(broken, others);
  const std::string text = slurp(dir + "/summary.txt");
  EXPECT_LT(text.find("results/passing:"), text.find("Case errors")) << text;
  EXPECT_LT(text.find("Case errors"), text.find("builtins/broken:")) << text;
  const nlohmann::json j = nlohmann::json::parse(slurp(dir + "/summary.json"));
  EXPECT_EQ(j["case_errors"], nlohmann::json::array({"builtins/broken"}));
  EXPECT_EQ(j["counts"]["CaseError"], 1);
}

TEST(Reports, UndefinedRaysAreShownPerCaseApartFromTheFindings) {
  const std::string dir = testing_support::testDir() + "/rayspec-report-test-undefined";
  ASSERT_EQ(errorText(writeReports(outcomesWithUndefinedBehaviour(), RunInfo{}, dir)), "");
  const std::string html = slurp(dir + "/report.html");
  const size_t probe = html.find("id=\"robustness/probe\"");
  const size_t table = html.find("<table class=\"undefined\">", probe);
  ASSERT_NE(table, std::string::npos);
  EXPECT_NE(html.find("<td>ray-parameters</td><td>3</td><td>0 4 7 </td><td>rays.list[0].tmin: NaN "
                      "&lt;tmin&gt;</td>",
                      table),
            std::string::npos)
      << html.substr(table, 400);
  const std::string text = slurp(dir + "/summary.txt");
  EXPECT_NE(
      text.find(
          "undefined (R-UB, not judged): ray-parameters, 3 rays; first: 0 4 7; rays.list[0].tmin"),
      std::string::npos)
      << text;
  const nlohmann::json j = nlohmann::json::parse(slurp(dir + "/summary.json"));
  for (const auto& c : j["cases"]) {
    if (c["name"] != "robustness/probe") continue;
    ASSERT_EQ(c["undefined"].size(), 1u);
    EXPECT_EQ(c["undefined"][0]["reason"], "ray-parameters");
    EXPECT_EQ(c["undefined"][0]["ray_count"], 3);
    EXPECT_EQ(c["undefined"][0]["rays"], nlohmann::json::array({0, 4, 7}));
    EXPECT_EQ(c["status"], "Pass");
  }
}

}  // namespace
}  // namespace rayspec

namespace rayspec {
namespace {

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = testing_support::testDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(Baseline, ExpectedFailureDoesNotFailTheRunAndIsReportedAsExpected) {
  std::string error;
  const Baseline b =
      orError(loadBaseline(writeTemp(
                  "baseline.csv",
                  "# lavapipe known failures\nfam/broken,Fail  # driver bug\nfam/fixed,Fail\n")),
              &error);
  ASSERT_EQ(error, "");
  ASSERT_EQ(b.expected.size(), 2u);
  CaseOutcome broken{"fam/broken", {}, Status::Fail, "Fail: x"};
  CaseOutcome fixed{"fam/fixed", {}, Status::Pass, "Pass"};
  CaseOutcome other{"fam/other", {}, Status::Fail, "Fail: y"};
  applyBaseline(b, broken);
  applyBaseline(b, fixed);
  applyBaseline(b, other);
  EXPECT_EQ(broken.baseline, BaselineMatch::Expected);
  EXPECT_EQ(fixed.baseline, BaselineMatch::UnexpectedPass);
  EXPECT_EQ(other.baseline, BaselineMatch::None);

  RunSummary expected_only(1);
  expected_only.add(broken);
  EXPECT_FALSE(expected_only.failed());
  RunSummary with_fixed(1);
  with_fixed.add(fixed);
  EXPECT_TRUE(with_fixed.failed())
      << "an unexpected pass fails the run until the baseline is updated";
  RunSummary with_new_failure(1);
  with_new_failure.add(other);
  EXPECT_TRUE(with_new_failure.failed()) << "a failure the baseline does not list fails the run";

  const std::string csv = testing_support::testDir() + "/baseline-results.csv";
  ASSERT_EQ(errorText(writeResultsCsv({broken, fixed, other}, csv)), "");
  std::ifstream in(csv);
  std::string a, c, d;
  std::getline(in, a);
  std::getline(in, c);
  std::getline(in, d);
  EXPECT_EQ(a.rfind("fam/broken,ExpectedFail,", 0), 0u) << a;
  EXPECT_EQ(c.rfind("fam/fixed,UnexpectedImprovement(Pass),", 0), 0u) << c;
  EXPECT_EQ(d.rfind("fam/other,Fail,", 0), 0u) << d;
}

TEST(Baseline, ADifferentBadStatusIsNotExpected) {
  std::string error;
  const Baseline b =
      orError(loadBaseline(writeTemp("baseline2.csv", "fam/a,QualityWarning\n")), &error);
  CaseOutcome crashed{"fam/a", {}, Status::Crash, "Crash"};
  applyBaseline(b, crashed);
  EXPECT_EQ(crashed.baseline, BaselineMatch::None);
}

TEST(Baseline, ReadsNamesBackFromResultsCsv) {
  // Names as results.csv writes them, read back by the baseline (quoted or not).
  const std::vector<std::string> names = {"fam/plain", "fam/sweep/variant-1.5_x", "a"};
  std::vector<CaseOutcome> outcomes;
  for (const std::string& n : names) outcomes.push_back({n, {}, Status::Fail, "Fail: x"});
  const std::string csv = testing_support::testDir() + "/quoted-results.csv";
  ASSERT_EQ(errorText(writeResultsCsv(outcomes, csv)), "");
  // A baseline made from results.csv: each line's name field as it was written, the rayspec status,
  // a comment.
  std::ifstream in(csv);
  std::string line, baseline_text = "# known failures\n";
  while (std::getline(in, line)) {
    const std::string name_field = line.substr(0, line.find(",Fail,"));
    baseline_text += name_field + ",Fail  # driver bug\n";
  }
  std::string error;
  const Baseline b = orError(loadBaseline(writeTemp("quoted-baseline.csv", baseline_text)), &error);
  ASSERT_EQ(error, "") << baseline_text;
  ASSERT_EQ(b.expected.size(), names.size()) << baseline_text;
  for (const std::string& n : names) {
    ASSERT_TRUE(b.expected.count(n)) << "'" << n << "' not read back from:\n" << baseline_text;
    EXPECT_EQ(b.expected.at(n), Status::Fail);
  }
  for (const std::string& n : names) EXPECT_EQ(csvFieldText(csvField(n)), n);
  // Names no case can have (a case name's parts are file names) are refused,
  // quoted or not: a typo or a stray byte would otherwise expect nothing.
  for (const std::string bad :
       {"\"fam/a,b\",Fail\n", "fam/hash#in,Fail\n", "fam//a,Fail\n", "fam/../a,Fail\n"}) {
    error.clear();
    orError(loadBaseline(writeTemp("bad-name-baseline.csv", bad)), &error);
    EXPECT_NE(error.find("bad-name-baseline.csv:1:"), std::string::npos) << bad << " -> " << error;
  }
}

TEST(Baseline, MalformedLineNamesFileAndLine) {
  std::string error;
  orError(loadBaseline(writeTemp("baseline3.csv", "fam/a,Fail\nfam/b,Broken\n")), &error);
  EXPECT_NE(error.find("baseline3.csv:2:"), std::string::npos) << error;
}

}  // namespace
}  // namespace rayspec

namespace rayspec {
namespace {

TEST(RunSummary, CountsNotSupportedCasesByWhatTheDeviceLacks) {
  RunSummary summary(3);
  const std::string lib = "pipeline.libraries: the device lacks VK_KHR_pipeline_library";
  summary.add({"fam/a", {}, Status::NotSupported, "vulkan: NotSupported: " + lib});
  summary.add({"fam/b", {}, Status::NotSupported, "vulkan: NotSupported: " + lib});
  summary.add({"fam/c", {}, Status::NotSupported, "vulkan: NotSupported: max_recursion 40 > 31"});
  testing::internal::CaptureStdout();
  summary.print();
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_NE(out.find("NotSupported, by what the device lacks:"), std::string::npos) << out;
  EXPECT_NE(out.find("      2  " + lib), std::string::npos) << out;
  EXPECT_NE(out.find("      1  max_recursion 40 > 31"), std::string::npos) << out;
}

TEST(RunSummary, CaseErrorsAreListedApartFromTheDevicesFailures) {
  RunSummary summary(4);
  testing::internal::CaptureStdout();
  for (const CaseOutcome& o : outcomesWithUndefinedBehaviour()) summary.add(o);
  summary.print();
  const std::string out = testing::internal::GetCapturedStdout();
  const size_t not_passing = out.find("Not passing"), errors = out.find("Case errors");
  ASSERT_NE(errors, std::string::npos) << out;
  EXPECT_LT(not_passing, out.find("  anyhit/failing", not_passing));
  EXPECT_LT(out.find("  anyhit/failing", not_passing), errors);
  EXPECT_NE(out.find("  builtins/broken", errors), std::string::npos) << out;
  EXPECT_EQ(out.find("  builtins/broken", not_passing), out.find("  builtins/broken", errors))
      << out;
  EXPECT_TRUE(summary.failed()) << "a case error fails the run";
}

// --brief (ctest): the progress and the summary name only what fails the run,
// so the first lines of a failing test's log are the failing cases.
TEST(RunSummary, BriefPrintsOnlyWhatFailsTheRun) {
  std::string error;
  const Baseline b =
      orError(loadBaseline(writeTemp("baseline-brief.csv", "fam/known,Fail\n")), &error);
  ASSERT_EQ(error, "");
  CaseOutcome known{"fam/known", {}, Status::Fail, "Fail: known"};
  CaseOutcome passing{"fam/passing", {}, Status::Pass, "Pass"};
  CaseOutcome unsupported{"fam/unsupported", {}, Status::NotSupported, "NotSupported: x"};
  CaseOutcome broken{"fam/broken", {}, Status::Fail, "Fail: new"};
  for (CaseOutcome* o : {&known, &passing, &unsupported, &broken}) applyBaseline(b, *o);
  RunSummary summary(4, RunSummary::Progress::Brief);
  testing::internal::CaptureStdout();
  for (const CaseOutcome& o : {known, passing, unsupported, broken}) summary.add(o);
  summary.print(true);
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_LT(out.find("[4/4] fam/broken"), out.find("==== rayspec summary")) << out;
  EXPECT_NE(out.find("  fam/broken "), std::string::npos) << out;
  for (const char* quiet : {"fam/known", "fam/passing", "fam/unsupported"})
    EXPECT_EQ(out.find(quiet), std::string::npos) << quiet << " in\n" << out;
  EXPECT_NE(out.find("NotSupported    1"), std::string::npos) << "the counts stay\n" << out;
  EXPECT_TRUE(summary.failed());
}

TEST(RuleCatalog, ErrorsNameFileLineAndWhatWasExpected) {
  const auto missing = loadRuleCatalog(testing_support::testDir() + "/no-such-catalog.yaml");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().format().find("no such rule catalog"), std::string::npos);
  EXPECT_EQ(missing.error().format().find("bad file"), std::string::npos);
  const std::string path = testing_support::testDir() + "/catalog-bad-title.yaml";
  std::ofstream(path) << "R-ONE: fine\nR-TWO: [not, a, title]\n";
  const auto bad = loadRuleCatalog(path);
  ASSERT_FALSE(bad);
  const std::string error = bad.error().format();
  EXPECT_EQ(error.rfind(path + ":2:8: R-TWO: expected the rule's title", 0), 0u) << error;
  EXPECT_EQ(error.find("bad conversion"), std::string::npos) << error;
  std::ofstream(path) << "R-ONE: first\nR-TWO: second\n";
  const auto rules = loadRuleCatalog(path);
  ASSERT_TRUE(rules) << rules.error().format();
  EXPECT_EQ(ruleLabels(*rules), (std::vector<std::string>{"R-ONE", "R-TWO"}));
}

}  // namespace
}  // namespace rayspec
