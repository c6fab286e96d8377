// The stability report's counting, table, JSON and plot panels
// (stability/leak_counts.h, stability/stability_table.h).
#include <gtest/gtest.h>

#include "results/record_layout.h"
#include "stability/leak_counts.h"
#include "stability/stability_table.h"

namespace rayspec {
namespace {

Results withAnyHitRuns(const std::vector<uint32_t>& runs) {
  Results r;
  const uint32_t words = recordWords(), ahit = findRecordField("any_hit_runs")->offset;
  r.records.assign(runs.size() * words, 0);
  for (size_t i = 0; i < runs.size(); ++i) r.records[i * words + ahit] = runs[i];
  return r;
}

TEST(LeakCounts, NoneIsALeakTwoOrMoreADoubleHit) {
  const LeakCounts c = countLeaks(withAnyHitRuns({1, 0, 2, 1, 7, 1, 1, 0}));
  EXPECT_EQ(c.rays, 8u);
  EXPECT_EQ(c.leaks, 2u);
  EXPECT_EQ(c.doubles, 2u);
  EXPECT_DOUBLE_EQ(c.leakRate(), 250.0);
  const LeakCounts clean = countLeaks(withAnyHitRuns({1, 1, 1}));
  EXPECT_EQ(clean.leaks + clean.doubles, 0u);
  EXPECT_EQ(LeakCounts{}.leakRate(), 0.0);
}

std::vector<StabilityEntry> sample() {
  std::vector<StabilityEntry> e;
  addCounts(e, {"grid", 1e6, "1e6", "model exact", {100, 0, 0}});
  addCounts(e, {"grid", 1, "1", "model exact", {100, 0, 0}});
  addCounts(e, {"grid", 1, "1", "lavapipe", {100, 3, 40}});
  addCounts(e,
            {"grid", 1, "1", "lavapipe", {100, 1, 0}});  // a second variant at the same magnitude
  addCounts(e, {"fan", 10, "1e1", "model exact", {50, 0, 0}});
  return e;
}

TEST(StabilityTable, SumsVariantsAndListsEachSourcesRates) {
  const std::vector<StabilityEntry> e = sample();
  ASSERT_EQ(e.size(), 4u);
  EXPECT_EQ(e[2].counts.rays, 200u);
  EXPECT_EQ(stabilitySources(e), (std::vector<std::string>{"model exact", "lavapipe"}));
  const std::string t = formatStabilityTable(e);
  // grid at 1: 200 rays, exact 0 / 0, lavapipe 4 leaks (20 per 1000) and 40 double hits (200 per
  // 1000).
  EXPECT_NE(
      t.find("grid                          1    200 |      0.0      0.0 |     20.0    200.0"),
      std::string::npos)
      << t;
  // Magnitudes ascend within a family; a source without a run shows '-'.
  EXPECT_LT(t.find("grid                          1 "), t.find("grid                        1e6"));
  EXPECT_NE(t.find("1e6    100 |      0.0      0.0 |                 -"), std::string::npos) << t;
  const nlohmann::json j = stabilityJson(e);
  EXPECT_EQ(j["entries"].size(), 4u);
  EXPECT_EQ(j["entries"][2]["double_hits"], 40u);
  EXPECT_DOUBLE_EQ(j["entries"][2]["double_hits_per_1000"].get<double>(), 200.0);
}

// The header names no planar meshes (the watertight meshes are not
// planar), and two drivers of one device name keep a column each: a bundle
// that names its driver is labelled by it, one that does not by its whole
// device name.
TEST(StabilityTable, TwoDriversOfOneDeviceNameKeepColumnsOfTheirOwn) {
  const std::string old_lvp =
      stabilityDeviceSource("llvmpipe (LLVM 15.0.6, 256 bits)", "Mesa 25.0.7");
  const std::string new_lvp =
      stabilityDeviceSource("llvmpipe (LLVM 15.0.6, 256 bits)", "Mesa 26.2.6 (git-1234)");
  EXPECT_EQ(old_lvp, "llvmpipe Mesa 25.0.7");
  EXPECT_EQ(new_lvp, "llvmpipe Mesa 26.2.6");
  EXPECT_EQ(stabilityDeviceSource("llvmpipe (LLVM 22.1.8, 256 bits)", ""),
            "llvmpipe (LLVM 22.1.8, 256 bits)");
  std::vector<StabilityEntry> e;
  addCounts(e, {"closed-fan-instances", 1, "1", old_lvp, {100, 0, 40}});
  addCounts(e, {"closed-fan-instances", 1, "1", new_lvp, {100, 0, 0}});
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(stabilitySources(e), (std::vector<std::string>{old_lvp, new_lvp}));
  const std::string t = formatStabilityTable(e);
  EXPECT_EQ(t.find("planar"), std::string::npos) << t;
  EXPECT_NE(t.find("| llvmpipe Mesa 25.0.7 | llvmpipe Mesa 26.2.6"), std::string::npos) << t;
  EXPECT_NE(t.find("closed-fan-instances          1    100 |"), std::string::npos) << t;
  EXPECT_NE(t.find("|         0.0    400.0 |         0.0      0.0"), std::string::npos) << t;
}

// Small multiples: a row per family, a panel per source in it, leaks and
// double hits in each; a row shares its y axis.
TEST(StabilityTable, APanelPerFamilyAndSourceTheRowSharingItsAxis) {
  const std::vector<PlotPanel> p = stabilityPanels(sample());
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p[0].title, "grid: model exact");
  EXPECT_EQ(p[1].title, "grid: lavapipe");
  EXPECT_EQ(p[2].title, "fan: model exact");
  EXPECT_TRUE(p[0].log_x);
  ASSERT_EQ(p[1].series.size(), 2u);
  EXPECT_EQ(p[1].series[0].name, "leaks");
  EXPECT_EQ(p[1].series[1].name, "double hits");
  EXPECT_EQ(p[0].series[0].points, (std::vector<std::pair<double, double>>{{1, 0}, {1e6, 0}}));
  EXPECT_EQ(p[1].series[1].points, (std::vector<std::pair<double, double>>{{1, 200}}));
  EXPECT_EQ(p[0].y_max, p[1].y_max);
  EXPECT_GE(p[0].y_max, 200);
  EXPECT_EQ(p[2].y_max, 1) << "a row with nothing to show still gets an axis";
}

}  // namespace
}  // namespace rayspec
