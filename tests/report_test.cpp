#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "report/baseline.h"
#include "report/run_summary.h"
#include "report/write_reports.h"

namespace rayspec {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

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

TEST(Reports, ResultsCsvIsDeqpRunnerCsv) {
  const std::string dir = ::testing::TempDir() + "/rayspec-report-test";
  ASSERT_EQ(writeReports(outcomes(), RunInfo{}, dir), "");
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

TEST(Reports, HtmlPutsFailingCasesFirstEscapesAndCarriesItsSelfCheck) {
  const std::string dir = ::testing::TempDir() + "/rayspec-report-test-html";
  ASSERT_EQ(writeReports(outcomes(), RunInfo{}, dir), "");
  const std::string html = slurp(dir + "/report.html");
  EXPECT_LT(html.find("id=\"anyhit/failing\""), html.find("id=\"results/passing\""));
  EXPECT_LT(html.find("id=\"watertight/leaky\""), html.find("id=\"results/passing\""));
  EXPECT_NE(html.find("&lt;odd&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<odd>"), std::string::npos);
  EXPECT_NE(html.find("brokenImages"), std::string::npos) << "the self-check a headless browser reads";
  EXPECT_NE(html.find("<td>primitive_id</td><td>3</td><td>2</td>"), std::string::npos);
}

}  // namespace
}  // namespace rayspec

namespace rayspec {
namespace {

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(Baseline, ExpectedFailureDoesNotFailTheRunAndIsReportedAsExpected) {
  std::string error;
  const Baseline b = loadBaseline(
      writeTemp("baseline.csv", "# lavapipe known failures\nfam/broken,Fail  # driver bug\nfam/fixed,Fail\n"), &error);
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

  RunSummary expected_only(2);
  expected_only.add(broken);
  expected_only.add(fixed);
  EXPECT_FALSE(expected_only.failed());
  RunSummary with_new_failure(1);
  with_new_failure.add(other);
  EXPECT_TRUE(with_new_failure.failed()) << "a failure the baseline does not list fails the run";

  const std::string csv = testing::TempDir() + "/baseline-results.csv";
  ASSERT_EQ(writeResultsCsv({broken, fixed, other}, csv), "");
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
  const Baseline b = loadBaseline(writeTemp("baseline2.csv", "fam/a,QualityWarning\n"), &error);
  CaseOutcome crashed{"fam/a", {}, Status::Crash, "Crash"};
  applyBaseline(b, crashed);
  EXPECT_EQ(crashed.baseline, BaselineMatch::None);
}

TEST(Baseline, MalformedLineNamesFileAndLine) {
  std::string error;
  loadBaseline(writeTemp("baseline3.csv", "fam/a,Fail\nfam/b,Broken\n"), &error);
  EXPECT_NE(error.find("baseline3.csv:2:"), std::string::npos) << error;
}

}  // namespace
}  // namespace rayspec
