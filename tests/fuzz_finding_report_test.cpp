// A fuzz finding's report.md quotes its rule from the rule catalog: the
// title, the text and the specification's section, for each rule of a
// combined label, and says when the catalog lacks one.
#include <gtest/gtest.h>

#include "fuzz/finding_report.h"

namespace rayspec {
namespace {

std::vector<Rule> catalog() {
  const Result<std::vector<Rule>> c =
      loadRuleCatalog(RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml");
  EXPECT_TRUE(c) << c.error().format();
  return c ? *c : std::vector<Rule>{};
}

const Rule& ruleOf(const std::vector<Rule>& rules, const std::string& label) {
  for (const Rule& r : rules)
    if (r.label == label) return r;
  static const Rule kNone;
  ADD_FAILURE() << label << " is not in the catalog";
  return kNone;
}

TEST(FuzzFindingReport, QuotesTheRuleOfItsSignature) {
  const std::vector<Rule> rules = catalog();
  FuzzOptions opt;
  opt.out = "fuzz-out";
  CaseOutcome o;
  o.name = "fuzz/seed-12";
  o.verdict.add({Status::Fail, "R-WATERTIGHT", "ray on a shared edge leaked", {}, 0});
  o.deriveFromVerdict();
  FuzzTally::Group g;
  g.signature = {"Fail", "R-WATERTIGHT", "ray on a shared edge leaked", "Fail_R-WATERTIGHT_x"};
  const std::string report = findingReport(opt, rules, 12, o, g);
  const Rule& r = ruleOf(rules, "R-WATERTIGHT");
  ASSERT_FALSE(r.text.empty());
  ASSERT_FALSE(r.spec.empty());
  EXPECT_NE(report.find("## R-WATERTIGHT: " + r.title), std::string::npos) << report;
  EXPECT_NE(report.find(r.text), std::string::npos) << report;
  EXPECT_NE(report.find("Specification: " + r.spec), std::string::npos) << report;
  // Another rule's text is not there.
  EXPECT_EQ(report.find(ruleOf(rules, "R-AABB-CONS").text), std::string::npos);
}

// A defect of ours has no rule of the catalog to quote.
TEST(FuzzFindingReport, ADefectOfOursQuotesNoRule) {
  FuzzTally::Group g;
  g.signature = {"CaseError", "generated-shader", "vulkan: invalid", "CaseError_x"};
  g.rayspec_defect = true;
  CaseOutcome o;
  o.verdict.add({Status::CaseError, "generated-shader", "vulkan: invalid", {}, 0});
  o.deriveFromVerdict();
  const std::string report = findingReport(FuzzOptions{}, catalog(), 3, o, g);
  EXPECT_EQ(report.find("## "), std::string::npos) << report;
  EXPECT_NE(report.find("a rayspec defect"), std::string::npos) << report;
}

TEST(FuzzFindingReport, EachRuleOfACombinedLabelAndAnUnknownOne) {
  const std::vector<Rule> rules = catalog();
  const std::string s = ruleSection(rules, "R-BUILTIN/R-NO-SUCH-RULE/R-AABB-CONS");
  EXPECT_NE(s.find("## R-BUILTIN: " + ruleOf(rules, "R-BUILTIN").title), std::string::npos) << s;
  EXPECT_NE(s.find("## R-AABB-CONS: " + ruleOf(rules, "R-AABB-CONS").title), std::string::npos)
      << s;
  EXPECT_NE(s.find("Specification: " + ruleOf(rules, "R-AABB-CONS").spec), std::string::npos);
  EXPECT_NE(s.find("## R-NO-SUCH-RULE\n\nNot in the rule catalog."), std::string::npos) << s;
}

}  // namespace
}  // namespace rayspec
