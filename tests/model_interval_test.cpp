// The ends of the ray interval in the exact tier (R-CAND-TRI-OPEN,
// R-CAND-AABB-CLOSED, R-TIE): exactly representable geometry is judged
// exactly (model/exact_interval.h), values that round stay ties.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "model/exact_interval.h"
#include "model_support.h"

namespace rayspec {
namespace {

using namespace model_test;

const std::set<std::array<uint32_t, 3>> kHitOrMiss = {{~0u, ~0u, ~0u}, {0, 0, 0}};

TEST(ExactInterval, Criterion) {
  const DVec3 v0{-1, -1, 0}, v1{1, -1, 0}, v2{1, 1, 0};
  // Axis-aligned, power-of-two directions, a perpendicular triangle, a grid.
  ExactEnds e = exactEnds({0.5, -0.5, 5}, {0, 0, -1}, v0, v1, v2, 5, 0.001, 5);
  EXPECT_TRUE(e.tmax);
  EXPECT_FALSE(e.tmin) << "t inside, tmin off the grid: no claim (and no tie: t is far from it)";
  e = exactEnds({0.5, -0.5, 5}, {0, 0, -0.5}, v0, v1, v2, 10, 10, 96);
  EXPECT_TRUE(e.tmin);
  EXPECT_FALSE(e.tmax) << "96 needs the grid to reach 2^7";
  EXPECT_TRUE(exactEnds({0.5, -0.5, 5}, {0, 0, -0.5}, v0, v1, v2, 10, 10, 12).tmax);
  // Not axis-aligned, not a power of two, not perpendicular: no claim.
  EXPECT_FALSE(exactEnds({0.5, -0.5, 5}, {0.25, 0, -1}, v0, v1, v2, 5, 0, 5).tmax);
  EXPECT_FALSE(exactEnds({0.5, -0.5, 5}, {0, 0, -3}, v0, v1, v2, 5.0 / 3, 0, 5.0 / 3).tmax);
  EXPECT_FALSE(exactEnds({0.5, -0.5, 5}, {0, 0, -1}, v0, v1, {1, 1, 0.5}, 4.75, 0, 4.75).tmax);
  // Values that need more bits than the grid allows (0.1f has 24).
  const double tenth = static_cast<double>(0.1f);
  EXPECT_FALSE(exactEnds({0.5, -0.5, 5}, {0, 0, -1}, {-1, -1, tenth}, {1, -1, tenth}, {1, 1, tenth},
                         5 - tenth, 0, 5 - tenth)
                   .tmax);
  // An exact t a float step inside an end that is off the grid: a device that
  // compares N with tmax * D may round the product onto N.
  const double above = std::nextafter(5.0f, 6.0f), below = std::nextafter(5.0f, 4.0f);
  EXPECT_FALSE(exactEnds({0.5, -0.5, 5}, {0, 0, -1}, v0, v1, v2, 5, 0, above).tmax);
  EXPECT_TRUE(exactEnds({0.5, -0.5, 5}, {0, 0, -1}, v0, v1, v2, 5, 0, below).tmax)
      << "t beyond tmax: monotonic";
  EXPECT_FALSE(exactEnds({0.5, -0.5, 5}, {0, 0, -1}, v0, v1, v2, 5, below, 10).tmin);
  EXPECT_TRUE(exactEnds({0.5, -0.5, 5}, {0, 0, -1}, v0, v1, v2, 5, above, 10).tmin);
}

// Moller-Trumbore as GPU code often writes it: t = N * rcp(D). With D's
// mantissa 41 (a projected doubled area of 41 / 4), t = 1 comes out
// 1 - 2^-24: no exact end there, the ray is a tie.
TEST(ExactInterval, ReciprocalMultiplyMustGiveTheSameT) {
  const float area = 41.0f, rcp = 1.0f / area;
  ASSERT_NE(area * rcp, 1.0f) << "the arithmetic this test is about";
  const DVec3 a{0, 0, 0}, b{10.25, 0, 0}, c{0, 1, 0};
  const ExactEnds e = exactEnds({0.25, 0.25, 1}, {0, 0, -1}, a, b, c, 1, 0.5, 1);
  EXPECT_FALSE(e.tmax);
  EXPECT_FALSE(e.tmin);
  // A power-of-two area: every reciprocal is exact.
  EXPECT_TRUE(exactEnds({0.25, 0.25, 1}, {0, 0, -1}, a, {8, 0, 0}, c, 1, 0.5, 1).tmax);
}

TEST(ExactInterval, ObjectRayOfAnInstance) {
  EXPECT_TRUE(objectRayExact(InstanceForm::Identity, kIdentity, {1000.3, 0.7, 5}));
  Transform t = kIdentity;
  t[3] = 10;
  EXPECT_TRUE(objectRayExact(InstanceForm::ScaledPermutation, t, {10.25, 0.5, 2}));
  t[0] = 2;  // a power-of-two scale keeps the inverse exact
  EXPECT_TRUE(objectRayExact(InstanceForm::ScaledPermutation, t, {10.25, 0.5, 2}));
  t[0] = 3;
  EXPECT_FALSE(objectRayExact(InstanceForm::ScaledPermutation, t, {10.25, 0.5, 2}));
  t = kIdentity;
  t[3] = 1000;  // lavapipe's inverse of this translation is off by one float step
  EXPECT_FALSE(
      objectRayExact(InstanceForm::ScaledPermutation, t, {static_cast<double>(1000.3f), 0.5, 2}));
  EXPECT_FALSE(objectRayExact(InstanceForm::General, t, {1000, 0, 2}));
}

// t == tmax and t == tmin with exact values: no candidate, and no tie (a
// device closing the interval is wrong). The same ends with a plane at 0.1f
// (t rounds on a device) stay ties with both answers.
TEST(Model, TriangleIntervalIsOpen) {
  for (ModelTier tier : kTiers) {
    Ray a = downRay(0.5f, -0.5f);
    a.tmax = 5;  // hit exactly at tmax: no
    Ray b = downRay(0.5f, -0.5f);
    b.tmin = 5;  // exactly at tmin: no
    Ray d = downRay(0.5f, -0.5f);
    d.tmax = 5.001f;
    Ray e = downRay(0.5f, -0.5f);
    e.direction = {0, 0, -2};
    e.tmax = 2.5f;  // t = 2.5 = tmax
    Ray f = downRay(0.5f, -0.5f);
    f.direction = {0, 0, -0.5f};
    f.tmin = 10;  // t = 10 = tmin
    Case c = baseCase({quad()}, {a, b, d, e, f});
    Results r = run(c, tier);
    // Embree's robust kernel rounds t at tmax below it on AVX2-only
    // processors (docs/model-and-accuracy.md, "Model tiers"): its tmax end
    // is not checked.
    const bool tmax_exact = tier != ModelTier::Robust;
    for (uint32_t ray : {0u, 1u, 3u, 4u}) {
      if (tmax_exact || ray == 1u || ray == 4u) {
        EXPECT_EQ(word(r, ray, "hit"), 0u) << modelTierName(tier) << " " << ray;
      }
    }
    EXPECT_EQ(word(r, 2, "hit"), 1u) << modelTierName(tier);
    EXPECT_TRUE(r.ambiguous.empty()) << modelTierName(tier);
  }
  const float z = 0.1f;
  Ray a = downRay(0.5f, -0.5f);
  a.tmax = 5 - z;  // 4.9f is above 5 - 0.1f: the model hits
  Ray b = downRay(0.5f, -0.5f);
  b.tmin = 5 - z;  // the model misses
  Case c = baseCase({quad(z)}, {a, b});
  Results r = run(c, ModelTier::Exact);
  auto amb = byRay(r);
  EXPECT_EQ(word(r, 0, "hit"), 1u);
  EXPECT_EQ(word(r, 1, "hit"), 0u);
  ASSERT_EQ(amb.count(0), 1u);
  EXPECT_EQ(amb[0]->reason, AmbiguityReason::TmaxTie);
  EXPECT_EQ(legal(*amb[0]), kHitOrMiss);
  ASSERT_EQ(amb.count(1), 1u);
  EXPECT_EQ(amb[1]->reason, AmbiguityReason::TminTie);
  EXPECT_EQ(legal(*amb[1]), kHitOrMiss);
}

// Exact t a float step inside an end off the grid: a tie; not
// axis-aligned: a tie; an instance translation on the grid: exact.
TEST(ExactInterval, WhereTheClaimStops) {
  Ray inside = downRay(0.5f, -0.5f);
  inside.tmax = std::nextafter(5.0f, 6.0f);
  Ray slanted = downRay(0.5f - 1.25f, -0.5f);
  slanted.direction = {0.25f, 0, -1};
  slanted.tmax = 5;
  Case c = baseCase({quad()}, {inside, slanted});
  Results r = run(c, ModelTier::Exact);
  auto amb = byRay(r);
  ASSERT_EQ(amb.count(0), 1u);
  EXPECT_EQ(amb[0]->reason, AmbiguityReason::TmaxTie);
  EXPECT_EQ(legal(*amb[0]), kHitOrMiss);
  ASSERT_EQ(amb.count(1), 1u);
  EXPECT_EQ(amb[1]->reason, AmbiguityReason::TmaxTie);

  Ray moved = downRay(10.5f, -0.5f);
  moved.tmax = 5;
  Case t = baseCase({quad()}, {moved});
  t.scene.instances[0].transform[3] = 10;
  Results rt = run(t, ModelTier::Exact);
  EXPECT_EQ(word(rt, 0, "hit"), 0u);
  EXPECT_TRUE(rt.ambiguous.empty());
  t.scene.instances[0].transform[11] = 0.1f;  // the plane at z = 0.1f: t rounds
  t.rays.rays[0].tmax = 5 - 0.1f;
  Results ru = run(t, ModelTier::Exact);
  ASSERT_EQ(ru.ambiguous.size(), 1u);
  EXPECT_EQ(ru.ambiguous[0].reason, AmbiguityReason::TmaxTie);
}

// Far from the origin an end is judged by the t error of the device's own
// frame, not by the magnitude of the world origin: a hit at t = 5 through an
// instance at 2^33 (scaled by 2^13, an exact inverse) is no tmin-tie at
// tmin = 0.001.
TEST(ExactInterval, EndToleranceLivesInTheTranslatedFrame) {
  const float big = 8589934592.0f, scale = 8192.0f;
  Ray r = downRay(big + 0.5f * scale, big - 0.5f * scale);
  Case c = baseCase({quad()}, {r});
  Transform& m = c.scene.instances[0].transform;
  m[0] = m[5] = scale;
  m[3] = m[7] = big;
  Results res = run(c, ModelTier::Exact);
  EXPECT_EQ(word(res, 0, "hit"), 1u);
  EXPECT_EQ(fword(res, 0, "hit_t"), 5.0f);
  EXPECT_TRUE(res.ambiguous.empty());
}

// A shared edge exactly at tmax: neither triangle is a candidate, so no
// what-if run may force one in: the ray is a clear miss.
TEST(ExactInterval, SharedEdgeAtAnExactEndIsAClearMiss) {
  Ray r0 = downRay(0.25f, 0.25f);
  r0.tmax = 5;
  Ray r1 = downRay(0.25f, 0.25f);
  Case c = baseCase({quad()}, {r0, r1});
  Results r = run(c, ModelTier::Exact);
  auto amb = byRay(r);
  EXPECT_EQ(word(r, 0, "hit"), 0u);
  EXPECT_EQ(amb.count(0), 0u);
  ASSERT_EQ(amb.count(1), 1u) << "the same edge inside the interval is ambiguous";
  EXPECT_EQ(amb[1]->reason, AmbiguityReason::Edge);
}

// A shared edge whose t rounds across tmin or tmax on a device (NVIDIA fuzz
// seed 110968, issue 63: edges aimed at t = tmin): a device may find
// neither triangle, so a miss is a legal answer, no leak, and the reason is
// the interval end. The model's own t is above tmin (below tmax): it hits.
TEST(ExactInterval, SharedEdgeAtARoundedEndMayMissBoth) {
  const float z = 0.1f;
  Ray near_tmin = downRay(0.25f, 0.25f);
  near_tmin.tmin = std::nextafter(5 - z, 0.0f);
  Ray near_tmax = downRay(0.25f, 0.25f);
  near_tmax.tmax = 5 - z;
  Case c = baseCase({quad(z)}, {near_tmin, near_tmax});
  Results r = run(c, ModelTier::Exact);
  auto amb = byRay(r);
  const std::set<std::array<uint32_t, 3>> either_or_miss = {{~0u, ~0u, ~0u}, {0, 0, 0}, {0, 0, 1}};
  for (uint32_t ray : {0u, 1u}) {
    EXPECT_EQ(word(r, ray, "hit"), 1u) << ray;
    ASSERT_EQ(amb.count(ray), 1u) << ray;
    EXPECT_EQ(legal(*amb[ray]), either_or_miss) << ray;
    EXPECT_TRUE(amb[ray]->leak_answers.empty()) << ray;
  }
  EXPECT_EQ(amb[0]->reason, AmbiguityReason::TminTie);
  EXPECT_EQ(amb[1]->reason, AmbiguityReason::TmaxTie);
}

// R-CAND-AABB-CLOSED: reports at exactly the ray's tmin and tmax are
// accepted, and no tie: nothing is committed yet.
TEST(ExactInterval, AabbReportsAtTheEndsAreAccepted) {
  Ray a = downRay(0, 0);
  a.tmin = 1;
  a.tmax = 10;
  Case c = baseCase({boxes({{-1, -1, -1, 1, 1, 1}})}, {a, a});
  Stmt at_max;
  at_max.kind = Stmt::Kind::Report;
  at_max.t = bi("ray_tmax");
  at_max.hit_kind = lit(1);
  Stmt at_min = at_max;
  at_min.t = bi("ray_tmin");
  Stmt ok = recordExpr("value", lit(1)), no = recordExpr("value", lit(0));
  at_max.then_ = {ok};
  at_max.else_ = {no};
  at_min.then_ = {ok};
  at_min.else_ = {no};
  c.pipeline.hit_groups[0].intersection =
      Program{ifThen(op("eq", {bi("launch_id_x"), lit(0)}), {at_max}, {at_min})};
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  EXPECT_TRUE(r.ambiguous.empty());
  for (uint32_t ray : {0u, 1u}) {
    EXPECT_EQ(word(r, ray, "value"), 1u) << ray;
    EXPECT_EQ(word(r, ray, "hit"), 1u) << ray;
  }
  EXPECT_EQ(fword(r, 0, "hit_t"), 10.0f);
  EXPECT_EQ(fword(r, 1, "hit_t"), 1.0f);
}

}  // namespace
}  // namespace rayspec
