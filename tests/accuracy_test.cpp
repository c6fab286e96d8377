// The accuracy report's per-ray comparison, t errors in ULP, table, JSON and
// plot panels (accuracy/ray_disagreements.h, t_errors.h, accuracy_table.h).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>

#include "accuracy/accuracy_table.h"
#include "accuracy/ray_disagreements.h"
#include "accuracy/t_errors.h"
#include "library/case_discovery.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// A hand-made record: what the stages ran and recorded.
struct Ray {
  uint32_t chit = 0, ahit = 0, miss = 0;
  std::optional<uint32_t> primitive, instance;
  std::optional<float> t;
};

void set(uint32_t* rec, const char* field, uint32_t word) {
  rec[findRecordField(field)->offset] = word;
  const RecordField* f = findRecordField(field);
  if (!f->automatic) markWritten(rec, f->index);
}

Results bundle(const std::vector<Ray>& rays) {
  Results r;
  r.width = static_cast<uint32_t>(rays.size());
  r.height = 1;
  const uint32_t words = recordWords();
  r.records.assign(rays.size() * words, 0);
  for (size_t i = 0; i < rays.size(); ++i) {
    uint32_t* rec = &r.records[i * words];
    set(rec, "closest_hit_runs", rays[i].chit);
    set(rec, "any_hit_runs", rays[i].ahit);
    set(rec, "miss_runs", rays[i].miss);
    if (rays[i].primitive) set(rec, "primitive_id", *rays[i].primitive);
    if (rays[i].instance) set(rec, "instance_id", *rays[i].instance);
    if (rays[i].t) set(rec, "hit_t", std::bit_cast<uint32_t>(*rays[i].t));
  }
  return r;
}

Ray hitRay(uint32_t prim, float t, uint32_t ahit = 0) {
  return {1, ahit, 0, prim, 0u, t};
}
Ray missRay(uint32_t ahit = 0) {
  return {0, ahit, 1, {}, {}, {}};
}

float ulpsAbove(float t, int n) {
  for (int i = 0; i < n; ++i) t = std::nextafter(t, INFINITY);
  return t;
}

TEST(RayDisagreements, EachKindIsDetected) {
  const Results exact = bundle({
      hitRay(3, 2.0f),  // 0: agree exactly
      hitRay(3, 2.0f),  // 1: a leak: the other side misses
      missRay(1),       // 2: any-hit once (ignored), the other side twice: a double hit
      hitRay(3, 2.0f),  // 3: another primitive
      hitRay(5, 4.0f),  // 4: the same primitive, t 3 ULP off
      missRay(),        // 5: an extra hit on a clear ray
      missRay(1),       // 6: a leak of an any-hit-only ray (stability cases)
  });
  const Results other = bundle({
      hitRay(3, 2.0f),
      missRay(),
      missRay(2),
      hitRay(4, 2.0f),
      hitRay(5, ulpsAbove(4.0f, 3)),
      hitRay(1, 7.0f),
      missRay(0),
  });
  const Disagreements d = countDisagreements(exact, other, nullptr);
  EXPECT_EQ(d.rays, 7u);
  EXPECT_EQ(d.leaks, 2u);
  EXPECT_EQ(d.double_hits, 1u);
  EXPECT_EQ(d.other_primitive, 1u);
  EXPECT_EQ(d.extra_hits, 1u);
  EXPECT_EQ(d.disagreeing, 5u);
  EXPECT_NEAR(d.perMillion(), 5e6 / 7, 1e-6);
  // t errors where both hit the same primitive: rays 0 (0 ULP) and 4 (3 ULP).
  ASSERT_EQ(d.t.count(), 2u);
  EXPECT_DOUBLE_EQ(d.t.max(), 3.0);
  EXPECT_EQ(d.t.histogram()[0], 1u);
  EXPECT_EQ(d.t.histogram()[tErrorBin(3)], 1u);
  // Against itself nothing disagrees.
  const Disagreements self = countDisagreements(exact, exact, nullptr);
  EXPECT_EQ(self.disagreeing, 0u);
  EXPECT_EQ(self.t.max(), 0.0);
}

TEST(RayDisagreements, LegalAnswersOfAmbiguousRaysAndUndefinedRaysAreNoDisagreement) {
  Results exact =
      bundle({hitRay(3, 2.0f), hitRay(3, 2.0f), hitRay(3, 2.0f), hitRay(3, 2.0f), missRay()});
  const Results other =
      bundle({hitRay(4, 2.0f), missRay(), missRay(), hitRay(9, 2.0f), hitRay(1, 1.0f)});
  // Ray 0: an edge between primitives 3 and 4: either is legal.
  exact.ambiguous.push_back({0, AmbiguityReason::Edge, {{true, 0, 0, 3}, {true, 0, 0, 4}}, {}});
  // Ray 1: the outer border of a mesh: a miss is legal (one triangle).
  exact.ambiguous.push_back(
      {1, AmbiguityReason::Edge, {{true, 0, 0, 3}, {false, 0, 0, 0}}, {{true, 0, 0, 3}}});
  // Ray 2: a miss is legal, but two triangles share the crossing: a leak.
  exact.ambiguous.push_back({2,
                             AmbiguityReason::Edge,
                             {{true, 0, 0, 3}, {false, 0, 0, 0}},
                             {{true, 0, 0, 3}, {false, 0, 0, 4}}});
  // Ray 3: primitive 9 is not among the legal answers.
  exact.ambiguous.push_back({3, AmbiguityReason::Edge, {{true, 0, 0, 3}, {true, 0, 0, 4}}, {}});
  // Ray 4: undefined behaviour, never compared.
  exact.undefined.push_back({4, UndefinedReason::RayParameters, "rays"});
  const Disagreements d = countDisagreements(exact, other, nullptr);
  EXPECT_EQ(d.rays, 4u);
  EXPECT_EQ(d.leaks, 1u);
  EXPECT_EQ(d.other_primitive, 1u);
  EXPECT_EQ(d.extra_hits, 0u);
  EXPECT_EQ(d.disagreeing, 2u);
}

// A hit within rounding of tmin (a ray that starts on a surface) has a t of
// a few float steps of the coordinates near 0: millions of ULPs of t_exact
// apart on two sides that both hit the same triangle. It is no t error; the
// same pair on a clear ray, or on an edge, is one.
TEST(RayDisagreements, AHitAtATminTieHasNoTError) {
  Results exact = bundle({hitRay(3, 1e-13f), hitRay(3, 1e-13f), hitRay(3, 1e-13f)});
  const Results other = bundle({hitRay(3, 2e-7f), hitRay(3, 2e-7f), hitRay(3, 2e-7f)});
  exact.ambiguous.push_back({0, AmbiguityReason::TminTie, {{true, 0, 0, 3}, {false, 0, 0, 0}}, {}});
  exact.ambiguous.push_back({1, AmbiguityReason::Edge, {{true, 0, 0, 3}, {true, 0, 0, 4}}, {}});
  const Disagreements d = countDisagreements(exact, other, nullptr);
  EXPECT_EQ(d.disagreeing, 0u);
  ASSERT_EQ(d.t.count(), 2u);  // rays 1 and 2
  EXPECT_GT(d.t.max(), 1e6);
}

// With the case at hand its triangles tell a closed crossing from the outer
// border of the mesh: watertight/shared-edges is a 4x4 grid whose primitives
// 0 and 1 split the corner cell along the diagonal from the grid's corner.
TEST(RayDisagreements, TheCaseTellsASharedEdgeFromTheBorder) {
  const std::optional<CaseFile> f =
      findCase("watertight/shared-edges", "", RAYSPEC_SOURCE_DIR "/cases");
  ASSERT_TRUE(f.has_value());
  const ParseResult parsed = loadCase(*f, RAYSPEC_SOURCE_DIR "/cases");
  ASSERT_TRUE(parsed.value.has_value());
  Results exact = bundle({hitRay(0, 3.0f), hitRay(0, 3.0f), hitRay(0, 3.0f)});
  const Results other = bundle({missRay(), missRay(), missRay()});
  // Ray 0: through the diagonal that primitives 0 and 1 share: a leak.
  exact.ambiguous.push_back({0, AmbiguityReason::Edge, {{true, 0, 0, 0}, {true, 0, 0, 1}}, {}});
  // Ray 1: through the grid's corner vertex, the fan open: a miss is legal
  // although the candidates list none (precision/large-coordinates has such rays).
  exact.ambiguous.push_back({1, AmbiguityReason::Vertex, {{true, 0, 0, 0}, {true, 0, 0, 1}}, {}});
  // Ray 2: through a border edge of primitive 0 alone.
  exact.ambiguous.push_back(
      {2, AmbiguityReason::Edge, {{true, 0, 0, 0}, {false, 0, 0, 0}}, {{true, 0, 0, 0}}});
  EXPECT_EQ(countDisagreements(exact, other, &*parsed.value).leaks, 1u);
  // Without the case only the candidates tell: the corner ray lists no miss.
  EXPECT_EQ(countDisagreements(exact, other, nullptr).leaks, 2u);
}

TEST(RayDisagreements, DifferentLaunchesCompareNothing) {
  EXPECT_EQ(countDisagreements(bundle({missRay()}), bundle({missRay(), missRay()}), nullptr).rays,
            0u);
}

TEST(TErrors, UlpsAtTheExactDistance) {
  EXPECT_EQ(ulpError(1.0f, 1.0f), 0.0);
  EXPECT_DOUBLE_EQ(ulpError(ulpsAbove(1.0f, 1), 1.0f), 1.0);
  EXPECT_DOUBLE_EQ(ulpError(ulpsAbove(1000.0f, 7), 1000.0f), 7.0);
  // Below a power of two the spacing of t_exact counts: 1 - 2^-24 is half an ULP of 1.
  EXPECT_DOUBLE_EQ(ulpError(std::nextafter(1.0f, 0.0f), 1.0f), 0.5);
  EXPECT_TRUE(std::isnan(ulpError(NAN, 1.0f)));
  EXPECT_TRUE(std::isnan(ulpError(1.0f, INFINITY)));
}

TEST(TErrors, QuantilesAndPowerOfTwoHistogram) {
  TErrors e;
  for (int i = 1; i <= 100; ++i) e.add(i);
  e.add(NAN);  // left out
  EXPECT_EQ(e.count(), 100u);
  EXPECT_EQ(e.median(), 50.0);
  EXPECT_EQ(e.p99(), 99.0);
  EXPECT_EQ(e.max(), 100.0);
  EXPECT_EQ(tErrorBin(0), 0u);
  EXPECT_EQ(tErrorBin(0.5), 1u);
  EXPECT_EQ(tErrorBin(1), 1u);
  EXPECT_EQ(tErrorBin(2), 2u);
  EXPECT_EQ(tErrorBin(3), 3u);
  EXPECT_EQ(tErrorBin(4), 3u);
  EXPECT_EQ(tErrorBin(1e12), kTErrorBins - 1);
  EXPECT_EQ(tErrorBinLabel(3), "4");
  EXPECT_EQ(tErrorBinLabel(kTErrorBins - 1), ">32768");
  // 1, 2, (3, 4], (4, 8], ... (64, 128]: 1 + 1 + 2 + 4 + 8 + 16 + 32 + 36.
  EXPECT_EQ(e.histogram()[1], 1u);
  EXPECT_EQ(e.histogram()[2], 1u);
  EXPECT_EQ(e.histogram()[3], 2u);
  EXPECT_EQ(e.histogram()[8], 36u);
  TErrors none;
  EXPECT_EQ(none.median(), 0.0);
}

std::vector<AccuracyRow> sampleRows() {
  std::vector<AccuracyRow> rows;
  AccuracyRow fast{CaseSet::Hard, "model fast", SourceKind::ModelTier, 1, 1000, 0.002, {}};
  fast.d.rays = 1000;
  fast.d.leaks = fast.d.disagreeing = 4;
  addToRow(rows, fast);
  addToRow(rows, fast);  // a second case
  AccuracyRow exact{CaseSet::Hard, "model exact", SourceKind::ModelTier, 1, 2000, 0.01, {}};
  exact.d.rays = 2000;
  addToRow(rows, exact);
  AccuracyRow dev{CaseSet::Ordinary, "llvmpipe", SourceKind::Device, 1, 1000000, 2.0, {}};
  dev.d.rays = 1000000;
  dev.d.t.add(3);
  addToRow(rows, dev);
  return rows;
}

TEST(AccuracyTable, RowsSumCasesAndGiveTimePerMray) {
  const std::vector<AccuracyRow> rows = sampleRows();
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].cases, 2u);
  EXPECT_EQ(rows[0].d.leaks, 8u);
  EXPECT_DOUBLE_EQ(rows[0].msPerMray(), 2000.0);  // 4 ms for 2000 rays
  EXPECT_DOUBLE_EQ(rows[0].d.perMillion(), 4000.0);
  const std::string t = formatAccuracyTable(rows);
  EXPECT_LT(t.find("ordinary cases"), t.find("hard cases")) << t;
  EXPECT_NE(t.find("model fast         2      2000    2000.00    4000.0       8"),
            std::string::npos)
      << t;
  const nlohmann::json j = accuracyJson(rows);
  ASSERT_EQ(j["rows"].size(), 3u);
  EXPECT_EQ(j["rows"][2]["source"], "llvmpipe");
  EXPECT_EQ(j["rows"][2]["kind"], "device");
  EXPECT_EQ(j["rows"][2]["set"], "ordinary");
  EXPECT_DOUBLE_EQ(j["rows"][2]["ms_per_mray"].get<double>(), 2000.0);
  EXPECT_EQ(j["rows"][2]["t_error_ulp"]["max"], 3.0);
  EXPECT_EQ(j["rows"][2]["t_error_ulp"]["histogram"][3]["rays"], 1u);
}

TEST(AccuracyTable, OneScatterPanelPerSetZeroAtTheFloor) {
  const std::vector<PlotPanel> p = accuracyPanels(sampleRows());
  ASSERT_EQ(p.size(), 2u);
  EXPECT_FALSE(p[1].lines);
  EXPECT_TRUE(p[1].log_x && p[1].log_y);
  ASSERT_EQ(p[1].series.size(), 2u);
  EXPECT_EQ(p[1].series[0].points, (std::vector<std::pair<double, double>>{{2000.0, 4000.0}}));
  EXPECT_EQ(p[1].series[1].points[0].second,
            kPlotFloorPerMillion);  // the exact tier: no disagreement
  EXPECT_EQ(p[1].series[1].key, "model exact (0)");
  EXPECT_EQ(p[1].series[1].name, "model exact") << "the colour follows the source";
}

}  // namespace
}  // namespace rayspec
