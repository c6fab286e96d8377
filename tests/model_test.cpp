// Unit tests of the CPU reference model: hand-built cases per rule family,
// outcomes derived from the geometry (helpers: model_support.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <set>

#include "model/model_scene.h"
#include "model/sphere_error.h"
#include "model/watertight.h"
#include "model_support.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "program/ops.h"
#include "results/record_layout.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

using namespace model_test;

// ---- tests ----------------------------------------------------------------

TEST(ModelTier, Parses) {
  EXPECT_EQ(parseModelTier("fast"), ModelTier::Fast);
  EXPECT_EQ(parseModelTier("robust"), ModelTier::Robust);
  EXPECT_EQ(parseModelTier("exact"), ModelTier::Exact);
  EXPECT_FALSE(parseModelTier("slow").has_value());
}

TEST(Model, QuadCenterHitsThePrimitiveContainingIt) {
  for (ModelTier tier : kTiers) {
    Case c = baseCase({quad()}, {downRay(0.5f, -0.5f), downRay(-0.5f, 0.5f), downRay(3, 3)});
    Results r = run(c, tier);
    ASSERT_EQ(r.statusText(), "ok");
    EXPECT_EQ(r.backend, "model");
    EXPECT_EQ(r.device, std::string("embree-") + modelTierName(tier));
    EXPECT_EQ(word(r, 0, "hit"), 1u);
    EXPECT_EQ(word(r, 0, "primitive_id"), 0u);
    EXPECT_EQ(word(r, 1, "primitive_id"), 1u);
    EXPECT_NEAR(fword(r, 0, "hit_t"), 5.0f, 1e-5);
    EXPECT_EQ(word(r, 0, "hit_kind"), 0xFEu);  // seen from +z: front
    EXPECT_EQ(word(r, 2, "hit"), 0u);
    EXPECT_TRUE(written(r, 2, "hit"));
    EXPECT_FALSE(written(r, 2, "primitive_id"));
    EXPECT_EQ(r.counters["miss"], 1u);
    EXPECT_EQ(r.counters["closesthit"], 2u);
    EXPECT_EQ(word(r, 0, "closest_hit_runs"), 1u);
    EXPECT_EQ(word(r, 2, "miss_runs"), 1u);
    EXPECT_EQ(word(r, 0, "raygen_runs"), 1u);
  }
}

Case anyHitGridCase() {
  std::vector<Ray> rays;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      rays.push_back(downRay(-0.97f + x * 0.0613f, -0.97f + y * 0.0613f));
  Case c = baseCase({grid(4, 0)}, rays, 32);
  c.pipeline.hit_groups[0].any_hit = Program{
      count("anyhit"),
      ifThen(op("odd", {bi("primitive_id")}), {count("ignored"), simple(Stmt::Kind::Ignore)})};
  return c;
}

TEST(Model, AnyHitIgnoringOddPrimitivesLeavesOnlyEven) {
  for (ModelTier tier : kTiers) {
    Case c = anyHitGridCase();
    Results r = run(c, tier);
    ASSERT_EQ(r.statusText(), "ok");
    uint32_t hits = 0, misses = 0;
    for (uint32_t i = 0; i < 32 * 32; ++i) {
      EXPECT_EQ(word(r, i, "closest_hit_runs") + word(r, i, "miss_runs"), 1u);
      if (word(r, i, "hit")) {
        ++hits;
        EXPECT_EQ(word(r, i, "primitive_id") % 2, 0u) << "ray " << i;
      } else {
        ++misses;
      }
      EXPECT_GE(word(r, i, "any_hit_runs"), 1u);
    }
    EXPECT_GT(hits, 300u);
    EXPECT_GT(misses, 300u);
    EXPECT_EQ(r.counters["ignored"], misses);
    EXPECT_EQ(r.counters["closesthit"], hits);
  }
}

TEST(Model, OpaqueGeometrySkipsAnyHit) {
  Case c = anyHitGridCase();
  c.scene.blases[0].geometries[0].flags = kGeometryOpaque;
  Results r = run(c, ModelTier::Exact);
  EXPECT_EQ(r.counters["anyhit"], 0u);
  EXPECT_EQ(r.counters["miss"], 0u);
  // force_no_opaque on the instance brings it back; the ray flag opaque wins over it.
  c.scene.instances[0].flags = kInstanceForceNoOpaque;
  EXPECT_GT(run(c, ModelTier::Fast).counters["anyhit"], 0u);
  for (Ray& ray : c.rays.rays) ray.flags = kRayOpaque;
  EXPECT_EQ(run(c, ModelTier::Fast).counters["anyhit"], 0u);
}

TEST(Model, ThreadCountDoesNotChangeResults) {
  for (ModelTier tier : kTiers) {
    Case c = anyHitGridCase();
    Results a = run(c, tier, 1), b = run(c, tier, 4);
    EXPECT_EQ(a.records, b.records);
    EXPECT_EQ(a.counters, b.counters);
    EXPECT_EQ(a.ambiguous.size(), b.ambiguous.size());
  }
}

// Rays over a 16x16 opaque grid (some miss it), 40x40 launch.
std::vector<Ray> gridRays() {
  std::vector<Ray> rays;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x) {
      Ray r = downRay(-1.2f + 2.4f * (x + 0.37f) / 40, -1.2f + 2.4f * (y + 0.61f) / 40);
      r.direction = {0.01f * (x % 3), -0.02f * (y % 2), -1};
      rays.push_back(r);
    }
  return rays;
}

// The direct path (raygen `trace: {}`, Embree's own closest hit, chunks
// traced then shaded, count-only programs without a stage environment) gives
// what the general interpreter gives, whatever the thread count.
TEST(Model, DirectChunkedPathMatchesGeneralPath) {
  for (ModelTier tier : {ModelTier::Fast, ModelTier::Robust}) {
    Case direct = baseCase({grid(16, kGeometryOpaque)}, gridRays(), 40);
    Case general = direct;
    general.pipeline.raygen = {count("calls"), traceStmt()};  // not `trace: {}` alone
    Results d1 = run(direct, tier, 1), d3 = run(direct, tier, 3), g = run(general, tier, 1);
    ASSERT_EQ(d1.statusText(), "ok");
    EXPECT_EQ(d1.records, g.records);
    EXPECT_EQ(d1.records, d3.records);
    EXPECT_EQ(d1.counters["closesthit"], g.counters["closesthit"]);
    EXPECT_EQ(d1.counters["miss"], g.counters["miss"]);
    EXPECT_EQ(g.counters["calls"], 1600u);
    EXPECT_GT(d1.counters["closesthit"], 0u);
    EXPECT_GT(d1.counters["miss"], 0u);
    EXPECT_EQ(d1.counters, d3.counters);
    // Hit kinds come from the facing, computed only because closest-hit reads it.
    for (uint32_t i = 0; i < 1600; ++i) {
      if (word(d1, i, "hit") == 1) {
        EXPECT_EQ(word(d1, i, "hit_kind"), 0xFEu) << i;
      }
    }

    // Counters only: no records at all, the same counts.
    Case counts = direct;
    counts.pipeline.miss = {{count("miss")}};
    counts.pipeline.hit_groups[0].closest_hit = Program{count("closesthit"), count("calls")};
    counts.outputs.per_ray.clear();
    Results k1 = run(counts, tier, 1), k2 = run(counts, tier, 2);
    EXPECT_TRUE(k1.records.empty());
    EXPECT_EQ(k1.counters["closesthit"], d1.counters["closesthit"]);
    EXPECT_EQ(k1.counters["calls"], d1.counters["closesthit"]);
    EXPECT_EQ(k1.counters["miss"], d1.counters["miss"]);
    EXPECT_EQ(k1.counters, k2.counters);
  }
}

// The direct path's per-block resolution of counts-only programs: rays of one
// block with other trace parameters (another miss index, SkipClosestHit), two
// instances whose hit groups differ (one counts only, one reads launch_id_x),
// counters only: the same counts as the general interpreter, any thread count.
TEST(Model, DirectPathMixedTraceParametersMatchGeneralPath) {
  std::vector<Ray> rays;
  const uint32_t w = 64, h = 9;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      Ray r = downRay(-2.5f + 5.0f * (x + 0.5f) / w, -1.5f + 3.0f * (y + 0.5f) / h);
      const uint32_t i = y * w + x;
      if (i % 5 == 0) r.miss = 1;
      if (i % 7 == 0) r.flags = kRaySkipClosestHit;
      rays.push_back(r);
    }
  Case direct = baseCase({grid(4, kGeometryOpaque)}, rays, w);
  direct.scene.instances.push_back(direct.scene.instances[0]);
  direct.scene.instances[0].transform[3] = -1;  // x in [-2, 0]
  direct.scene.instances[1].transform[3] = 1;   // x in [0, 2]
  direct.scene.instances[1].sbt_offset = 1;
  direct.pipeline.miss = {{count("miss")}, {count("far_accepted")}};
  HitGroup g0, g1;
  g0.closest_hit = Program{count("closesthit")};
  g1.closest_hit =
      Program{ifThen(op("eq", {bi("launch_id_x"), lit(40)}), {count("ignored")}), count("calls")};
  direct.pipeline.hit_groups = {g0, g1};
  direct.outputs.per_ray.clear();
  Case general = direct;
  general.pipeline.raygen = {traceStmt(), count("near_accepted")};
  for (ModelTier tier : {ModelTier::Fast, ModelTier::Robust}) {
    Results g = run(general, tier, 1);
    ASSERT_EQ(g.statusText(), "ok");
    EXPECT_EQ(g.counters["near_accepted"], w * h);
    g.counters.erase("near_accepted");
    for (const char* k : {"miss", "far_accepted", "closesthit", "calls", "ignored"})
      EXPECT_GT(g.counters[k], 0u) << k;
    for (unsigned threads : {1u, 2u, 5u}) {
      Results d = run(direct, tier, threads);
      ASSERT_EQ(d.statusText(), "ok");
      EXPECT_TRUE(d.records.empty());
      d.counters.erase("near_accepted");
      EXPECT_EQ(d.counters, g.counters) << modelTierName(tier) << " threads " << threads;
    }
  }
}

// Compiled programs keep the meaning of ops (arithmetic, comparisons,
// vectors, short-circuit and/or) per ray.
// On each of the 1600 rays of gridRays() that hit, value == expect(ray); and
// more than 100 hit.
void expectValueOnHits(const Results& r, const std::function<uint32_t(uint32_t)>& expect) {
  int hits = 0;
  for (uint32_t i = 0; i < 1600; ++i) {
    if (word(r, i, "hit") != 1) continue;
    ++hits;
    EXPECT_EQ(word(r, i, "value"), expect(i)) << "ray " << i;
  }
  EXPECT_GT(hits, 100);
}

TEST(Model, CompiledOpsPerRay) {
  Case c = baseCase({grid(4, kGeometryOpaque)}, gridRays(), 40);
  Program chit;
  chit.push_back(recordExpr("hit", lit(1)));
  chit.push_back(recordExpr("primitive_id", bi("primitive_id")));
  // value = primitive_id * 3 + (launch_id_x mod 5), or 7 when primitive is odd and x < 20.
  chit.push_back(
      ifThen(op("and", {op("odd", {bi("primitive_id")}), op("lt", {bi("launch_id_x"), lit(20)})}),
             {recordExpr("value", lit(7))},
             {recordExpr("value", op("add", {op("mul", {bi("primitive_id"), lit(3)}),
                                             op("mod", {bi("launch_id_x"), lit(5)})}))}));
  c.pipeline.hit_groups[0].closest_hit = chit;
  Results r = run(c, ModelTier::Fast, 2);
  ASSERT_EQ(r.statusText(), "ok");
  expectValueOnHits(r, [&r](uint32_t i) {
    const uint32_t p = word(r, i, "primitive_id"), x = i % 40;
    return (p & 1) && x < 20 ? 7 : p * 3 + x % 5;
  });
}

// round: to the nearest whole number, halfway cases to even (GLSL roundEven).
TEST(Model, RoundIsHalfToEven) {
  Case c = baseCase({grid(4, kGeometryOpaque)}, gridRays(), 40);
  Program chit;
  chit.push_back(recordExpr("hit", lit(1)));
  // value = round(launch_id_x / 2): x = 1, 3, 5, ... are halfway cases.
  chit.push_back(recordExpr(
      "value",
      op("uint", {op("round", {op("mul", {op("float", {bi("launch_id_x")}), litf(0.5)})})})));
  c.pipeline.hit_groups[0].closest_hit = chit;
  Results r = run(c, ModelTier::Fast, 2);
  ASSERT_EQ(r.statusText(), "ok");
  expectValueOnHits(r, [](uint32_t i) {
    const uint32_t x = i % 40, half = x / 2;
    return x % 2 == 0 ? half : (half % 2 == 0 ? half : half + 1);
  });
}

TEST(Model, FacingCullsFlipAndDisable) {
  Ray up = downRay(0.5f, -0.5f, -5);
  up.direction = {0, 0, 1};
  for (ModelTier tier : kTiers) {
    Case c = baseCase({quad()}, {downRay(0.5f, -0.5f), up});
    Results r = run(c, tier);
    EXPECT_EQ(word(r, 0, "hit_kind"), 0xFEu);
    EXPECT_EQ(word(r, 1, "hit_kind"), 0xFFu);
    for (Ray& ray : c.rays.rays) ray.flags = kRayCullBackFacing;
    r = run(c, tier);
    EXPECT_EQ(word(r, 0, "hit"), 1u);
    EXPECT_EQ(word(r, 1, "hit"), 0u);
    c.scene.instances[0].flags = kInstanceFlipFacing;
    r = run(c, tier);
    EXPECT_EQ(word(r, 0, "hit"), 0u);
    EXPECT_EQ(word(r, 1, "hit"), 1u);
    EXPECT_EQ(word(r, 1, "hit_kind"), 0xFEu);
    c.scene.instances[0].flags = kInstanceFlipFacing | kInstanceFacingCullDisable;
    r = run(c, tier);
    EXPECT_EQ(word(r, 0, "hit"), 1u);
    EXPECT_EQ(word(r, 0, "hit_kind"), 0xFFu);
  }
}

TEST(Model, MasksAndSkipFlags) {
  for (ModelTier tier : kTiers) {
    Case c = baseCase({quad()}, {downRay(0.5f, -0.5f), downRay(0.5f, -0.5f), downRay(0.5f, -0.5f),
                                 downRay(0.5f, -0.5f)});
    c.scene.instances[0].mask = 0x01;
    c.rays.rays[0].cull_mask = 0x02;
    c.rays.rays[1].cull_mask = 0x103;  // only the low 8 bits count
    c.rays.rays[2].flags = kRaySkipTriangles;
    c.rays.rays[3].flags = kRaySkipAabbs;
    Results r = run(c, tier);
    EXPECT_EQ(word(r, 0, "hit"), 0u);
    EXPECT_EQ(word(r, 1, "hit"), 1u);
    EXPECT_EQ(word(r, 2, "hit"), 0u);
    EXPECT_EQ(word(r, 3, "hit"), 1u);
    c.pipeline.flags = 0x1000;  // pipeline skip triangles
    r = run(c, tier);
    EXPECT_EQ(word(r, 1, "hit"), 0u);
  }
}

TEST(Model, SbtHitIndexUsesLowBitsOfOffsetAndStride) {
  for (ModelTier tier : {ModelTier::Fast, ModelTier::Exact}) {
    Geometry far = quad(-1);
    Geometry near = quad(0);
    Ray ray = downRay(0.5f, -0.5f);
    ray.sbt_offset = 0x11;  // low 4 bits: 1
    ray.sbt_stride = 0x12;  // low 4 bits: 2
    Case c = baseCase({far, near}, {ray});
    c.scene.instances[0].sbt_offset = 1;
    c.pipeline.hit_groups.clear();
    for (uint32_t k = 0; k < 6; ++k) {
      HitGroup g;
      g.closest_hit = Program{recordExpr("value", lit(k)), recordBuiltins({"geometry_index"})};
      c.pipeline.hit_groups.push_back(g);
    }
    Results r = run(c, tier);
    EXPECT_EQ(word(r, 0, "geometry_index"), 1u);
    EXPECT_EQ(word(r, 0, "value"), 1u + 1u * 2u + 1u);
    // An all-zero record: no closest-hit runs, and no miss either.
    c.pipeline.sbt_hit = {{0, {}}, {1, {}}, {2, {}}, {3, {}}, {std::nullopt, {}}, {5, {}}};
    r = run(c, tier);
    EXPECT_EQ(word(r, 0, "closest_hit_runs"), 0u);
    EXPECT_EQ(word(r, 0, "miss_runs"), 0u);
  }
}

TEST(Model, ShaderRecordDataAndMissIndex) {
  Ray ray = downRay(5, 5);
  ray.miss = 0x10001;  // low 16 bits: 1
  Case c = baseCase({quad()}, {ray});
  c.pipeline.miss.push_back({recordExpr("value", op("shader_record_uint", {lit(2)}))});
  c.pipeline.sbt_miss = {{0, {}}, {1, {7, 8, 9}}};
  Results r = run(c, ModelTier::Exact);
  EXPECT_EQ(word(r, 0, "value"), 9u);
  EXPECT_EQ(r.counters["miss"], 0u);
}

TEST(Model, SphereIntersectionReportsBothRoots) {
  for (ModelTier tier : kTiers) {
    Geometry g;
    g.kind = Geometry::Kind::Aabbs;
    g.aabbs = {{-1, -1, -1, 1, 1, 1}};
    g.flags = kGeometryOpaque;
    Case c = baseCase({g}, {downRay(0, 0), downRay(0.9f, 0.9f)});
    Stmt far;
    far.kind = Stmt::Kind::Report;
    far.t = op("sphere_far", {});
    far.hit_kind = lit(2);
    far.then_ = {count("far_accepted")};
    Stmt near = far;
    near.t = op("sphere_near", {});
    near.hit_kind = lit(1);
    near.then_ = {count("near_accepted")};
    c.pipeline.hit_groups[0].intersection = Program{ifThen(op("sphere_hit", {}), {far, near})};
    c.pipeline.hit_groups[0].closest_hit->push_back(recordBuiltins({"ray_tmax"}));
    Results r = run(c, tier);
    ASSERT_EQ(r.statusText(), "ok");
    EXPECT_EQ(word(r, 0, "hit"), 1u);
    EXPECT_NEAR(fword(r, 0, "hit_t"), 4.0f, 1e-5);
    EXPECT_EQ(word(r, 0, "hit_kind"), 1u);
    EXPECT_FLOAT_EQ(fword(r, 0, "ray_tmax"), fword(r, 0, "hit_t"));
    EXPECT_EQ(word(r, 0, "intersection_runs"), 1u);
    EXPECT_EQ(word(r, 1, "hit"), 0u);  // corner of the box: outside the sphere
    EXPECT_EQ(word(r, 1, "intersection_runs"), 1u);
    EXPECT_EQ(r.counters["far_accepted"], 1u);
    EXPECT_EQ(r.counters["near_accepted"], 1u);
  }
}

// Exact tier: a ray grazing an AABB face may or may not reach the
// intersection program on a device; when that changes the answer, the ray is
// ambiguous ("aabb-face") with both answers legal. Clear rays stay clear.
TEST(Model, AabbFaceGrazingIsAmbiguousInExactTier) {
  Geometry g;
  g.kind = Geometry::Kind::Aabbs;
  g.aabbs = {{-1, -1, -1, 1, 1, 1}};
  g.flags = kGeometryOpaque;
  // 0: inside, 1: on the face x = 1, 2: just outside it, 3: far outside.
  Case c = baseCase(
      {g}, {downRay(0.5f, 0), downRay(1.0f, 0), downRay(1.0f + 1e-7f, 0), downRay(1.5f, 0)});
  Stmt rep;
  rep.kind = Stmt::Kind::Report;
  rep.t = litf(4.5);
  rep.hit_kind = lit(3);  // always reports
  c.pipeline.hit_groups[0].intersection = Program{rep};
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  EXPECT_EQ(word(r, 0, "hit"), 1u);
  EXPECT_EQ(word(r, 3, "hit"), 0u);
  std::map<uint32_t, const RayAmbiguity*> amb;
  for (const RayAmbiguity& a : r.ambiguous) amb[a.ray] = &a;
  EXPECT_EQ(amb.count(0), 0u);
  EXPECT_EQ(amb.count(3), 0u);
  for (uint32_t ray : {1u, 2u}) {
    ASSERT_EQ(amb.count(ray), 1u) << ray;
    EXPECT_EQ(amb[ray]->reason, AmbiguityReason::AabbFace);
    bool hit = false, miss = false;
    for (const Candidate& k : amb[ray]->candidates) (k.hit ? hit : miss) = true;
    EXPECT_TRUE(hit && miss) << ray;
  }
  // A grazing ray whose answer cannot change (nothing reported) stays clear.
  c.pipeline.hit_groups[0].intersection = Program{count("calls")};
  Results quiet = run(c, ModelTier::Exact);
  EXPECT_TRUE(quiet.ambiguous.empty());
}

TEST(Model, InactiveAabbAndNullInstance) {
  Geometry g;
  g.kind = Geometry::Kind::Aabbs;
  g.aabbs = {{NAN, -1, -1, 1, 1, 1}};
  Case c = baseCase({g}, {downRay(0, 0)});
  Stmt rep;
  rep.kind = Stmt::Kind::Report;
  rep.t = litf(1.0);
  rep.hit_kind = lit(0);
  c.pipeline.hit_groups[0].intersection = Program{rep};
  Results r = run(c, ModelTier::Exact);
  EXPECT_EQ(word(r, 0, "hit"), 0u);
  EXPECT_EQ(word(r, 0, "intersection_runs"), 0u);
  Case q = baseCase({quad()}, {downRay(0.5f, -0.5f)});
  q.scene.instances[0].blas.reset();
  EXPECT_EQ(word(run(q, ModelTier::Fast), 0, "hit"), 0u);
}

TEST(Model, CallableDataFlowsBack) {
  Case c = baseCase({quad()}, {downRay(0.5f, -0.5f)});
  Stmt call;
  call.kind = Stmt::Kind::Call;
  call.call_index = lit(1);
  call.assigns = {{"value", lit(41)}};
  c.pipeline.hit_groups[0].closest_hit = Program{call, recordExpr("value", bi("callee.value"))};
  Stmt set;
  set.kind = Stmt::Kind::SetCall;
  set.assigns = {{"value", op("add", {bi("call.value"), lit(1)})}};
  c.pipeline.callables = {{count("calls")}, {count("calls"), set}};
  Results r = run(c, ModelTier::Exact);
  EXPECT_EQ(word(r, 0, "value"), 42u);
  EXPECT_EQ(word(r, 0, "callable_runs"), 1u);
  EXPECT_EQ(r.counters["calls"], 1u);
}

TEST(Model, PointLightFormula) {
  Case c = baseCase({quad()}, {downRay(0.5f, -0.5f)});
  Stmt call;
  call.kind = Stmt::Kind::Call;
  call.call_index = lit(0);
  call.assigns = {{"position", bi("hit_position")}, {"normal", vec3(0, 0, 1)}};
  c.pipeline.hit_groups[0].closest_hit = Program{call, recordExpr("color", bi("callee.color"))};
  Stmt light;
  light.kind = Stmt::Kind::Light;
  light.light = "point";
  c.pipeline.callables = {{light}};
  auto bits = [](float f) {
    return std::bit_cast<uint32_t>(f);
  };
  c.pipeline.sbt_callable = {
      {0, {bits(0.5f), bits(-0.5f), bits(2.0f), bits(1.0f), bits(0.5f), bits(0.25f)}}};
  c.outputs.per_ray.push_back("color");
  Results r = run(c, ModelTier::Fast);
  // Light straight above at distance 2: cos 1, 1/d^2 = 0.25.
  EXPECT_NEAR(fword(r, 0, "color", 0), 0.25f, 1e-6);
  EXPECT_NEAR(fword(r, 0, "color", 1), 0.125f, 1e-6);
  EXPECT_NEAR(fword(r, 0, "color", 3), 1.0f, 0);
}

TEST(Model, RecursionDepth) {
  Case c = baseCase({quad()}, {downRay(0.5f, -0.5f)});
  Stmt nested = traceStmt();
  nested.trace.origin = {vec3(5, 5, 5)};
  nested.trace.direction = {vec3(0, 0, -1)};
  c.pipeline.hit_groups[0].closest_hit = Program{traceStmt()};
  c.pipeline.hit_groups[0].closest_hit->back() = nested;
  c.pipeline.miss = {{recordBuiltins({"depth"})}};
  c.pipeline.max_recursion = 2;
  Results r = run(c, ModelTier::Exact);
  EXPECT_EQ(r.statusText(), "ok");
  EXPECT_EQ(word(r, 0, "depth"), 2u);
  EXPECT_EQ(word(r, 0, "miss_runs"), 1u);
  // Deeper than max_recursion: undefined (R-UB), diagnosed for the ray; the
  // run goes on and the nested trace is skipped.
  c.pipeline.max_recursion = 1;
  r = run(c, ModelTier::Exact);
  EXPECT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.undefined.size(), 1u);
  EXPECT_EQ(r.undefined[0].reason, UndefinedReason::RecursionTooDeep);
  EXPECT_EQ(word(r, 0, "miss_runs"), 0u);
}

TEST(Model, SharedEdgeIsAmbiguousInExactTierAndNeverLeaks) {
  std::vector<Ray> rays;
  for (int i = 0; i < 64; ++i) {
    float s = -0.9f + i * (1.8f / 63);
    rays.push_back(downRay(s, s));  // exactly on the diagonal shared by both triangles
  }
  rays.push_back(downRay(0.5f, -0.5f));  // clear
  Case c = baseCase({quad()}, rays);
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  for (uint32_t i = 0; i < 64; ++i) {
    EXPECT_EQ(word(r, i, "hit"), 1u) << "leak at ray " << i;
    EXPECT_EQ(word(r, i, "primitive_id"), 0u) << "tie-break: smallest primitive";
  }
  ASSERT_EQ(r.ambiguous.size(), 64u);
  for (const RayAmbiguity& a : r.ambiguous) {
    EXPECT_LT(a.ray, 64u);
    bool p0 = false, p1 = false;
    for (const Candidate& k : a.candidates) {
      p0 |= k.hit && k.primitive == 0;
      p1 |= k.hit && k.primitive == 1;
    }
    EXPECT_TRUE(p0 && p1) << ambiguityReasonName(a.reason);
  }
  EXPECT_EQ(r.ambiguous[0].reason, AmbiguityReason::Edge);
}

// Legal answers are the outcomes of what-if runs, not every candidate: on
// the diagonal shared by triangles 0 (kept) and 1 (ignored by any-hit), a
// device may hit 0, or find only 1 and miss; it may never report 1. No
// counter, payload or record effect of the what-if runs leaks into results.
TEST(Model, LegalAnswersFollowAnyHitOnSharedEdge) {
  std::vector<Ray> rays;
  for (int i = 0; i < 16; ++i) {
    float s = -0.9f + i * (1.8f / 15);
    rays.push_back(downRay(s, s));
  }
  Case c = baseCase({quad(0, 0)}, rays);
  c.pipeline.hit_groups[0].any_hit = Program{
      count("anyhit"),
      ifThen(op("odd", {bi("primitive_id")}), {count("ignored"), simple(Stmt::Kind::Ignore)})};
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 16u);
  for (const RayAmbiguity& a : r.ambiguous) {
    bool p0 = false, p1 = false, miss = false;
    for (const Candidate& k : a.candidates) {
      p0 |= k.hit && k.primitive == 0;
      p1 |= k.hit && k.primitive == 1;
      miss |= !k.hit;
    }
    EXPECT_TRUE(p0) << a.ray;
    EXPECT_TRUE(miss) << a.ray;
    EXPECT_FALSE(p1) << a.ray;
    // The actual run: the tie goes to the smaller key, 0, accepted; 1 is
    // then outside the open interval. What-if runs (1 alone: ignored) leave
    // no trace in the record or the counters.
    EXPECT_EQ(word(r, a.ray, "any_hit_runs"), 1u);
  }
  EXPECT_EQ(r.counters["anyhit"], 16u);
  EXPECT_EQ(r.counters["ignored"], 0u);
  EXPECT_EQ(r.counters["closesthit"], 16u);
}

TEST(Model, NanInYTriangleStaysActiveAndHugeTrianglesAreHit) {
  std::array<Vec3, 3> nan_y = {Vec3{0, NAN, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  std::array<Vec3, 3> nan_x = {Vec3{NAN, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  EXPECT_FALSE(triangleInactive(nan_y));
  EXPECT_TRUE(needsOwnTriangleTest(nan_y));
  EXPECT_TRUE(triangleInactive(nan_x));
  for (ModelTier tier : kTiers) {
    Geometry g;
    g.flags = kGeometryOpaque;
    // primitive 0: NaN in Y (active, Embree would drop it); 1: a normal triangle;
    // 2: huge (beyond Embree's 1.8e18 limit) far below.
    g.vertices = {{10, NAN, 0},          {11, 0, 0},           {10, 1, 0},
                  {-1, -1, 0},           {1, -1, 0},           {1, 1, 0},
                  {-4e18f, -4e18f, -10}, {4e18f, -4e18f, -10}, {0, 4e18f, -10}};
    Case c = baseCase({g}, {downRay(0.5f, -0.5f), downRay(-0.5f, 0.5f), downRay(10.2f, 0.2f)});
    Results r = run(c, tier);
    ASSERT_EQ(r.statusText(), "ok");
    EXPECT_EQ(word(r, 0, "primitive_id"), 1u);
    EXPECT_EQ(word(r, 1, "hit"), 1u) << "huge triangle dropped in " << modelTierName(tier);
    EXPECT_EQ(word(r, 1, "primitive_id"), 2u);
    EXPECT_NEAR(fword(r, 1, "hit_t"), 15.0f, 1e-4);
    EXPECT_EQ(word(r, 2, "primitive_id"), 2u) << "a NaN plane is never hit; behind it the huge one";
  }
}

// A triangle of the model's own test (here beyond Embree's range) in one BLAS
// takes the traces to the collect-then-process path: Embree's triangles of
// another BLAS must still reach it as candidates (fast and robust tiers).
TEST(Model, OwnTrianglesDoNotHideEmbreeTrianglesOfAnotherBlas) {
  Geometry huge;
  huge.flags = kGeometryOpaque;
  huge.vertices = {{-4e18f, -4e18f, -10}, {4e18f, -4e18f, -10}, {0, 4e18f, -10}};
  Case c = baseCase({quad()}, {downRay(0.5f, -0.5f), downRay(3, 3)});
  Blas far;
  far.name = "far";
  far.geometries = {huge};
  c.scene.blases.push_back(far);
  c.scene.instances.push_back(c.scene.instances[0]);
  c.scene.instances[1].blas = 1;
  for (ModelTier tier : kTiers) {
    Results r = run(c, tier);
    ASSERT_EQ(r.statusText(), "ok");
    EXPECT_EQ(word(r, 0, "hit"), 1u) << modelTierName(tier) << ": the quad in front";
    EXPECT_EQ(word(r, 0, "instance_id"), 0u) << modelTierName(tier);
    EXPECT_NEAR(fword(r, 0, "hit_t"), 5.0f, 1e-5) << modelTierName(tier);
    EXPECT_EQ(word(r, 1, "instance_id"), 1u) << modelTierName(tier) << ": beside it, the huge one";
  }
}

TEST(Model, ImagesFollowTheRecord) {
  Case c = baseCase({quad()}, {downRay(0.5f, -0.5f), downRay(3, 3)}, 2);
  c.outputs.images = {{"prim", "primitive_id", {}}, {"t", "hit_t", {}}};
  Results r = run(c, ModelTier::Fast);
  ASSERT_EQ(r.images.size(), 2u);
  EXPECT_FALSE(r.images[0].is_float);
  EXPECT_EQ(r.images[0].channels, 1u);
  EXPECT_TRUE(r.images[1].is_float);
  ASSERT_EQ(r.images[1].texels.size(), 8u);
  const float t = std::bit_cast<float>(r.images[1].texels[0]),
              a = std::bit_cast<float>(r.images[1].texels[3]);
  EXPECT_NEAR(t, 5.0f, 1e-5);
  EXPECT_EQ(a, 1.0f);
  EXPECT_EQ(r.images[1].texels[1], 0u);
}

TEST(Model, EveryCaseFileRunsInEveryTier) {
  namespace fs = std::filesystem;
  int ran = 0;
  for (const CaseFile& f : suiteCases()) {
    ParseResult p = loadSuiteCase(f);
    if (!p.value) {
      std::cerr << "skipping " << f.name << ": " << (p.errors.empty() ? "" : p.errors[0].format())
                << "\n";
      continue;
    }
    const Case& c = *p.value;
    const Plan plan = derivePlan(c);
    BulkWords fast_records;
    for (ModelTier tier : kTiers) {
      Results r = runOnModel(c, plan, ModelOptions{tier, 2});
      EXPECT_EQ(r.statusText(), "ok") << c.name << " " << modelTierName(tier);
      EXPECT_EQ(r.images.size(), plan.images.size()) << c.name;
      for (const std::string& name : plan.counters) EXPECT_EQ(r.counters.count(name), 1u) << name;
      if (!plan.records) {  // counters only: no record simulated at all
        EXPECT_TRUE(r.records.empty()) << c.name;
        continue;
      }
      ASSERT_EQ(r.records.size(), size_t(c.rays.width) * c.rays.height * recordWords()) << c.name;
      // One trace per launch: closest-hit xor miss (more traces run more).
      const bool one_trace = !plan.nested_trace && c.pipeline.raygen.size() == 1 &&
                             c.pipeline.raygen[0].kind == Stmt::Kind::Trace;
      for (uint32_t i = 0; i < c.rays.width * c.rays.height && one_trace; ++i)
        EXPECT_LE(word(r, i, "closest_hit_runs") + word(r, i, "miss_runs"), 1u)
            << c.name << " ray " << i;
      if (tier != ModelTier::Exact) continue;
      // Rays the exact tier calls clear agree with the fast tier.
      if (fast_records.empty()) {
        fast_records = runOnModel(c, plan, ModelOptions{ModelTier::Fast, 1}).records;
        std::vector<bool> amb(c.rays.width * c.rays.height, false);
        for (const RayAmbiguity& a : r.ambiguous) amb[a.ray] = true;
        uint32_t differ = 0;
        const uint32_t words = recordWords();
        for (uint32_t i = 0; i < c.rays.width * c.rays.height; ++i) {
          if (amb[i]) continue;
          if (word(r, i, "hit") != fast_records[i * words + findRecordField("hit")->offset] ||
              word(r, i, "primitive_id") !=
                  fast_records[i * words + findRecordField("primitive_id")->offset])
            ++differ;
        }
        EXPECT_EQ(differ, 0u) << c.name;
      }
    }
    ++ran;
  }
  EXPECT_GT(ran, 0);
}

}  // namespace
}  // namespace rayspec
