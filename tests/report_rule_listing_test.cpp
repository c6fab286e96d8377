// The rule listing: sweeps grouped, probes apart, uncovered and unknown rules.
#include <gtest/gtest.h>

#include "report/rule_listing.h"

namespace rayspec {
namespace {

const std::vector<Rule> kCatalog = {
    {"R-MASK", "masks"}, {"R-SBT-HIT", "hit index"}, {"R-UB", "undefined"}};

TEST(RuleListing, SweepsAreGroupedAndProbesApart) {
  const RuleListing l = listRules(kCatalog, {{"culling/a", "", {"R-MASK"}},
                                             {"sbt/s/o1", "sbt/s", {"R-SBT-HIT", "R-MASK"}},
                                             {"sbt/s/o2", "sbt/s", {"R-SBT-HIT"}},
                                             {"robustness/p", "", {"R-UB"}}});
  EXPECT_TRUE(l.uncovered.empty());
  EXPECT_TRUE(l.unknown.empty());
  EXPECT_NE(l.text.find("R-MASK  masks\n  culling/a\n  sbt/s (sweep: 1 variant)\n  2 cases\n"),
            std::string::npos)
      << l.text;
  EXPECT_NE(l.text.find("R-SBT-HIT  hit index\n  sbt/s (sweep: 2 variants)\n  2 cases\n"),
            std::string::npos);
  EXPECT_NE(l.text.find("R-UB  undefined\n  (probes:"), std::string::npos);
  EXPECT_NE(l.text.find("2 of 2 rules have a case (R-UB apart: 1 probe); 4 cases in all"),
            std::string::npos);
}

TEST(RuleListing, UncoveredAndUnknownRulesAreNamed) {
  const RuleListing l = listRules(kCatalog, {{"culling/a", "", {"R-MASK", "R-NEW"}}});
  EXPECT_EQ(l.uncovered,
            std::vector<std::string>{"R-SBT-HIT"});  // R-UB without a probe is not uncovered
  EXPECT_EQ(l.unknown, std::vector<std::string>{"R-NEW"});
  EXPECT_NE(l.text.find("R-SBT-HIT  hit index\n  UNCOVERED: no case claims this rule\n"),
            std::string::npos);
  EXPECT_NE(l.text.find("R-NEW  NOT IN THE CATALOG"), std::string::npos);
  EXPECT_NE(l.text.find("Uncovered: R-SBT-HIT\n"), std::string::npos);
}

}  // namespace
}  // namespace rayspec
