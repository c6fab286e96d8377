// report.html at scale: the counts by family and rule at its top, and a size
// that grows with the failures, a short row per passing case.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "read_text.h"
#include "report/report_tally.h"
#include "report/write_reports.h"
#include "result_support.h"
#include "test_dir.h"

namespace rayspec {
namespace {

CaseOutcome pageCase(const std::string& name, Status status, std::vector<std::string> rules) {
  CaseOutcome o;
  o.name = name;
  o.status = status;
  o.rules = std::move(rules);
  o.headline = statusName(status);
  return o;
}

// Two families and a case at the top; a failure whose finding names a rule
// the case claims and one it does not, beside a Pass note under a label that
// is no rule.
std::vector<CaseOutcome> tallyCases() {
  std::vector<CaseOutcome> v;
  v.push_back(pageCase("anyhit/a", Status::Pass, {"R-A", "R-B"}));
  v.push_back(pageCase("anyhit/b", Status::Fail, {"R-A"}));
  v.back().verdict.add({Status::Pass, "planted-fault", "a note", {}, 0});
  v.back().verdict.add({Status::Fail, "R-C/R-A", "hit_t differs", {4}, 1});
  v.push_back(pageCase("sbt/c", Status::NotSupported, {"R-B"}));
  v.push_back(pageCase("loose", Status::Pass, {}));
  return v;
}

TEST(ReportTally, CountsCasesByFamilyAndByRule) {
  const std::vector<CaseOutcome> v = tallyCases();
  EXPECT_EQ(familyLabel("anyhit/through-libraries/every-group"), "anyhit");
  EXPECT_EQ(familyLabel("loose"), "(none)");
  EXPECT_EQ(findingRules(v[1].verdict.findings[1]), (std::vector<std::string>{"R-C", "R-A"}));
  EXPECT_EQ(caseRules(v[1]), (std::vector<std::string>{"R-A", "R-C"}));

  auto families = tallyByFamily(v);
  ASSERT_EQ(families.size(), 3u);
  EXPECT_EQ(families["anyhit"].cases, 2);
  EXPECT_EQ(families["anyhit"].by_status[Status::Pass], 1);
  EXPECT_EQ(families["anyhit"].by_status[Status::Fail], 1);
  EXPECT_EQ(families["sbt"].by_status[Status::NotSupported], 1);
  EXPECT_EQ(families["(none)"].cases, 1);

  auto rules = tallyByRule(v);
  ASSERT_EQ(rules.size(), 3u) << "a case without rules counts under none";
  EXPECT_EQ(rules["R-A"].cases, 2);
  EXPECT_EQ(rules["R-A"].by_status[Status::Fail], 1);
  EXPECT_EQ(rules["R-A"].failing_findings, 1) << "named second by the failing finding";
  EXPECT_EQ(rules["R-B"].failing_findings, 0) << "its case passed";
  EXPECT_EQ(rules["R-B"].by_status[Status::Pass], 1);
  EXPECT_EQ(rules["R-B"].by_status[Status::NotSupported], 1);
  EXPECT_EQ(rules["R-C"].cases, 1) << "named only by a finding";
  EXPECT_EQ(rules["R-C"].failing_findings, 1);
}

TEST(ReportPage, SummaryCountsLinkToTheFilterThatShowsThem) {
  const std::string dir = testing_support::testDir() + "/rayspec-report-page-summary";
  RunInfo info;
  info.catalog = {{"R-A", "rule a"}, {"R-Z", "rule z"}};
  info.coverage = {{"R-A", {"anyhit/a", "anyhit/b"}}, {"R-Z", {}}};
  ASSERT_EQ(errorText(writeReports(tallyCases(), info, dir)), "");
  const std::string html = slurp(dir + "/report.html");
  EXPECT_NE(html.find("<tr><td>anyhit</td><td class=\"n\"><a href=\"#filter?family=anyhit\">2</a>"
                      "</td><td class=\"n\"><a href=\"#filter?family=anyhit&amp;status=Pass\">1"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<tr><td>R-C</td><td>(not in the catalog)</td><td class=\"n\">0</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<tr><td class=\"uncovered\">R-Z</td><td>rule z</td><td "
                      "class=\"n\">uncovered</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<a href=\"#filter?rule=R-C&amp;status=Fail\">1</a>"), std::string::npos);
  // The filter offers every family and rule, and the cases carry what it matches.
  for (const char* option : {"value=\"anyhit\"", "value=\"sbt\"", "value=\"(none)\"",
                             "value=\"R-C\"", "value=\"NotSupported\""})
    EXPECT_NE(html.find(option), std::string::npos) << option;
  EXPECT_NE(html.find("id=\"anyhit/b\" data-s=\"Fail\" data-f=\"anyhit\">"), std::string::npos);
  EXPECT_NE(html.find("rules: <span class=\"r\">R-A R-C</span>"), std::string::npos);
}

// A family name with bytes a link must encode: the link's value, decoded,
// is the option's value and the case's data-f.
TEST(ReportPage, FilterLinksEncodeTheValueTheOptionsHold) {
  const std::string path = testing_support::testDir() + "/rayspec-report-page-encoding.html";
  ASSERT_EQ(errorText(writeReportHtml({pageCase("odd fam&\xff/c", Status::Pass, {"R-A"})},
                                      RunInfo{}, path)),
            "");
  const std::string html = slurp(path);
  EXPECT_NE(html.find("<a href=\"#filter?family=odd%20fam%26%5CxFF\">1</a>"), std::string::npos)
      << html;
  EXPECT_NE(html.find("<option value=\"odd fam&amp;\\xFF\">"), std::string::npos);
  EXPECT_NE(html.find("data-f=\"odd fam&amp;\\xFF\""), std::string::npos);
}

// A failure of 5 rays, 14 fields each, one of them differing per ray.
CaseOutcome syntheticFailure(int i) {
  CaseOutcome o = pageCase("family" + std::to_string(i % 7) + "/failing-case-" + std::to_string(i),
                           Status::Fail, {"R-IGNORE", "R-MISS-XOR-CHIT"});
  o.verdict.add({Status::Fail, "R-IGNORE", "per-ray field 'hit_t' differs", {1, 2, 3, 4, 5}, 5});
  for (uint32_t ray = 1; ray <= 5; ++ray)
    for (int f = 0; f < 14; ++f)
      o.failing_rays.push_back({ray, ray, 0, "field_" + std::to_string(f),
                                f == 3 ? "1.5" : std::to_string(f), std::to_string(f)});
  return o;
}

size_t pageBytes(int passing, int failing, const std::string& name) {
  std::vector<CaseOutcome> v;
  for (int i = 0; i < passing; ++i)
    v.push_back(pageCase("family" + std::to_string(i % 7) + "/passing-case-" + std::to_string(i),
                         Status::Pass, {"R-IGNORE", "R-MISS-XOR-CHIT"}));
  for (int i = 0; i < failing; ++i) v.push_back(syntheticFailure(i));
  const std::string dir = testing_support::testDir() + "/rayspec-report-page-" + name;
  EXPECT_EQ(errorText(writeReports(v, RunInfo{}, dir)), "");
  return slurp(dir + "/report.html").size();
}

TEST(ReportPage, GrowsByAShortRowPerPassingCaseAndABoundedBlockPerFailure) {
  const size_t failures_only = pageBytes(0, 40, "failures-only");
  const size_t with_passing = pageBytes(1000, 40, "with-passing");
  const size_t more_failures = pageBytes(1000, 80, "more-failures");
  const double per_passing = (with_passing - failures_only) / 1000.0;
  const double per_failure = (more_failures - with_passing) / 40.0;
  EXPECT_LT(per_passing, 200.0) << "bytes per passing case";
  EXPECT_LT(per_failure, 6000.0) << "bytes per failure of 5 rays, 70 per-ray rows";
  EXPECT_LT(with_passing, 500u * 1000u);
}

TEST(ReportPage, FailuresShowTheirFindingsAndFoldTheRaysShowingOnlyDifferingFields) {
  std::vector<CaseOutcome> v{pageCase("fam/ok", Status::Pass, {"R-IGNORE"}), syntheticFailure(1)};
  const std::string dir = testing_support::testDir() + "/rayspec-report-page-rays";
  ASSERT_EQ(errorText(writeReports(v, RunInfo{}, dir)), "");
  const std::string html = slurp(dir + "/report.html");
  const size_t block = html.find("id=\"family1/failing-case-1\"");
  const size_t details = html.find("<details>", block), rays = html.find("class=\"rays\"", block);
  ASSERT_NE(details, std::string::npos);
  EXPECT_LT(html.find("per-ray field &#39;hit_t&#39; differs", block), details)
      << "the findings before the fold";
  EXPECT_LT(details, rays);
  EXPECT_NE(html.find("<summary>per-ray table: 5 rays, 5 differing fields of 70</summary>"),
            std::string::npos);
  size_t same = 0, differing = 0;
  for (size_t at = html.find("<tr class=\"same\"><td>field_", rays); at != std::string::npos;
       at = html.find("<tr class=\"same\"><td>field_", at + 1))
    ++same;
  for (size_t at = html.find("<tr><td>field_3</td><td>1.5</td><td>3</td>", rays);
       at != std::string::npos; at = html.find("<tr><td>field_3</td><td>1.5</td>", at + 1))
    ++differing;
  EXPECT_EQ(same, 65u) << "rows where device and model agree, hidden by default";
  EXPECT_EQ(differing, 5u);
  EXPECT_NE(html.find("<tr class=\"same\"><td>field_0</td><td colspan=\"2\">0</td></tr>", rays),
            std::string::npos)
      << "an agreeing field's one value";
  EXPECT_NE(html.find("table.rays:not(.all) tr.same{display:none}"), std::string::npos);
  EXPECT_NE(html.find("class=\"allf\"> every field"), std::string::npos)
      << "the switch to every field";
  EXPECT_EQ(html.find("<details>", html.find("id=\"fam/ok\"")), std::string::npos)
      << "no fold, images or rays for a passing case";
}

}  // namespace
}  // namespace rayspec
