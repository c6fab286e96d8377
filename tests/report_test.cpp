#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

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
