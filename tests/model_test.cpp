// Unit tests of the CPU reference model: hand-built cases per rule family,
// outcomes derived from the geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <array>

#include "case/parse_case.h"
#include "model/model_backend.h"
#include "model/model_scene.h"
#include "model/sphere_error.h"
#include "model/watertight.h"
#include "plan/plan.h"
#include "program/ops.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// ---- building cases -------------------------------------------------------

Expr lit(uint32_t v) { Expr e; e.kind = Expr::Kind::Literal; e.type = ValueType::Uint; e.literal = {double(v)}; return e; }
Expr litf(double v) { Expr e; e.kind = Expr::Kind::Literal; e.type = ValueType::Float; e.literal = {v}; return e; }
Expr vec3(double x, double y, double z) {
  Expr e; e.kind = Expr::Kind::Literal; e.type = ValueType::Vec3; e.literal = {x, y, z}; return e;
}
Expr bi(const std::string& n) { Expr e; e.kind = Expr::Kind::Builtin; e.name = n; return e; }
Expr op(const std::string& n, std::vector<Expr> args) {
  Expr e; e.kind = Expr::Kind::Op; e.name = n; e.args = std::move(args); return e;
}
Stmt count(const std::string& n) { Stmt s; s.kind = Stmt::Kind::Count; s.counter = n; return s; }
Stmt recordBuiltins(const std::vector<std::string>& fields) {
  Stmt s; s.kind = Stmt::Kind::Record;
  for (const auto& f : fields) s.assigns.push_back({f, bi(f)});
  return s;
}
Stmt recordExpr(const std::string& f, Expr e) { Stmt s; s.kind = Stmt::Kind::Record; s.assigns.push_back({f, e}); return s; }
Stmt simple(Stmt::Kind k) { Stmt s; s.kind = k; return s; }
Stmt ifThen(Expr cond, Program then_, Program else_ = {}) {
  Stmt s; s.kind = Stmt::Kind::If; s.cond = cond; s.then_ = then_; s.else_ = else_; return s;
}
Stmt traceStmt() { Stmt s; s.kind = Stmt::Kind::Trace; return s; }

Geometry quad(float z = 0, uint32_t flags = kGeometryOpaque) {
  Geometry g;
  g.vertices = {{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}};
  g.indices = {0, 1, 2, 0, 2, 3};
  g.flags = flags;
  return g;
}

// n x n cells on [-1,1]^2 at z = 0, two triangles a cell.
Geometry grid(int n, uint32_t flags) {
  Geometry g;
  g.flags = flags;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) g.vertices.push_back({-1 + 2.0f * i / n, -1 + 2.0f * j / n, 0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      g.indices.insert(g.indices.end(), {a, b, c, a, c, d});
    }
  return g;
}

Ray downRay(float x, float y, float z = 5) {
  Ray r; r.origin = {x, y, z}; r.direction = {0, 0, -1}; r.tmin = 0.001f; r.tmax = 100; return r;
}

// A case with one BLAS "b" of the given geometries, one identity instance,
// a miss recording hit 0 and one hit group recording the usual fields.
Case baseCase(std::vector<Geometry> geoms, std::vector<Ray> rays, uint32_t width = 0) {
  Case c;
  c.name = "model-test";
  Blas b; b.name = "b"; b.geometries = std::move(geoms);
  c.scene.blases.push_back(b);
  c.scene.instances.push_back(Instance{});
  c.scene.instances[0].blas = 0;
  c.rays.width = width ? width : static_cast<uint32_t>(rays.size());
  c.rays.height = static_cast<uint32_t>(rays.size()) / c.rays.width;
  c.rays.rays = std::move(rays);
  c.rays.defaults.tmin = 0.001f;
  c.rays.defaults.tmax = 100;
  c.pipeline.raygen = {traceStmt()};
  c.pipeline.miss = {{count("miss"), recordExpr("hit", lit(0))}};
  HitGroup g;
  g.closest_hit = Program{count("closesthit"), recordBuiltins({"hit", "primitive_id", "hit_t", "hit_kind", "instance_id", "geometry_index"})};
  c.pipeline.hit_groups = {g};
  c.outputs.counters = {"miss", "closesthit", "anyhit", "ignored", "far_accepted", "near_accepted", "calls"};
  c.outputs.per_ray = {"hit", "primitive_id", "hit_t", "hit_kind", "instance_id", "geometry_index", "value", "depth", "ray_tmax"};
  return c;
}

void checkAll(Case& c) {
  auto check = [&](Program& p, Stage s) {
    auto err = checkProgram(p, s, c.outputs.counters, c.outputs.per_ray);
    ASSERT_FALSE(err) << stageName(s) << ": " << err->message;
  };
  check(c.pipeline.raygen, Stage::Raygen);
  for (auto& m : c.pipeline.miss) check(m, Stage::Miss);
  for (auto& g : c.pipeline.hit_groups) {
    if (g.closest_hit) check(*g.closest_hit, Stage::ClosestHit);
    if (g.any_hit) check(*g.any_hit, Stage::AnyHit);
    if (g.intersection) check(*g.intersection, Stage::Intersection);
  }
  for (auto& k : c.pipeline.callables) check(k, Stage::Callable);
}

Results run(Case& c, ModelTier tier, unsigned threads = 2) {
  checkAll(c);
  Plan plan = derivePlan(c);
  ModelOptions o; o.tier = tier; o.threads = threads;
  return runOnModel(c, plan, o);
}

uint32_t word(const Results& r, uint32_t ray, const char* field, uint32_t k = 0) {
  return r.records[static_cast<size_t>(ray) * recordWords() + findRecordField(field)->offset + k];
}
float fword(const Results& r, uint32_t ray, const char* field, uint32_t k = 0) {
  uint32_t w = word(r, ray, field, k); float f; std::memcpy(&f, &w, 4); return f;
}
bool written(const Results& r, uint32_t ray, const char* field) {
  return (r.records[static_cast<size_t>(ray) * recordWords()] >> recordFieldIndex(field)) & 1u;
}

const ModelTier kTiers[] = {ModelTier::Fast, ModelTier::Robust, ModelTier::Exact};

// ---- tests ----------------------------------------------------------------

TEST(ModelTier, Parses) {
  EXPECT_EQ(parseModelTier("fast"), ModelTier::Fast);
  EXPECT_EQ(parseModelTier("robust"), ModelTier::Robust);
  EXPECT_EQ(parseModelTier("exact"), ModelTier::Exact);
  EXPECT_THROW(parseModelTier("slow"), std::invalid_argument);
}

TEST(Watertight, InsideOutsideEdge) {
  DVec3 v0{-1, -1, 0}, v1{1, -1, 0}, v2{1, 1, 0};
  auto h = watertightIntersect({0.5, -0.5, 5}, {0, 0, -1}, v0, v1, v2);
  EXPECT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 5.0, 1e-12);
  EXPECT_EQ(h.ambiguity, TriAmbiguity::None);
  EXPECT_FALSE(watertightIntersect({-0.5, 0.5, 5}, {0, 0, -1}, v0, v1, v2).hit);
  auto e = watertightIntersect({0.25, 0.25, 5}, {0, 0, -1}, v0, v1, v2);  // on the diagonal
  EXPECT_TRUE(e.hit);
  EXPECT_EQ(e.ambiguity, TriAmbiguity::Edge);
  auto v = watertightIntersect({1, 1, 5}, {0, 0, -1}, v0, v1, v2);
  EXPECT_EQ(v.ambiguity, TriAmbiguity::Vertex);
  // degenerate (line) triangle never hits
  EXPECT_FALSE(watertightIntersect({0, 0, 5}, {0, 0, -1}, {-1, 0, 0}, {0, 0, 0}, {1, 0, 0}).hit);
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
    for (int x = 0; x < 32; ++x) rays.push_back(downRay(-0.97f + x * 0.0613f, -0.97f + y * 0.0613f));
  Case c = baseCase({grid(4, 0)}, rays, 32);
  c.pipeline.hit_groups[0].any_hit =
      Program{count("anyhit"), ifThen(op("odd", {bi("primitive_id")}), {count("ignored"), simple(Stmt::Kind::Ignore)})};
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
    for (uint32_t i = 0; i < 1600; ++i)
      if (word(d1, i, "hit") == 1) EXPECT_EQ(word(d1, i, "hit_kind"), 0xFEu) << i;

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
  g1.closest_hit = Program{ifThen(op("eq", {bi("launch_id_x"), lit(40)}), {count("ignored")}), count("calls")};
  direct.pipeline.hit_groups = {g0, g1};
  direct.outputs.per_ray.clear();
  Case general = direct;
  general.pipeline.raygen = {traceStmt(), count("near_accepted")};
  for (ModelTier tier : {ModelTier::Fast, ModelTier::Robust}) {
    Results g = run(general, tier, 1);
    ASSERT_EQ(g.statusText(), "ok");
    EXPECT_EQ(g.counters["near_accepted"], w * h);
    g.counters.erase("near_accepted");
    for (const char* k : {"miss", "far_accepted", "closesthit", "calls", "ignored"}) EXPECT_GT(g.counters[k], 0u) << k;
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
TEST(Model, CompiledOpsPerRay) {
  Case c = baseCase({grid(4, kGeometryOpaque)}, gridRays(), 40);
  Program chit;
  chit.push_back(recordExpr("hit", lit(1)));
  chit.push_back(recordExpr("primitive_id", bi("primitive_id")));
  // value = primitive_id * 3 + (launch_id_x mod 5), or 7 when primitive is odd and x < 20.
  chit.push_back(ifThen(op("and", {op("odd", {bi("primitive_id")}), op("lt", {bi("launch_id_x"), lit(20)})}),
                        {recordExpr("value", lit(7))},
                        {recordExpr("value", op("add", {op("mul", {bi("primitive_id"), lit(3)}),
                                                         op("mod", {bi("launch_id_x"), lit(5)})}))}));
  c.pipeline.hit_groups[0].closest_hit = chit;
  Results r = run(c, ModelTier::Fast, 2);
  ASSERT_EQ(r.statusText(), "ok");
  int hits = 0;
  for (uint32_t i = 0; i < 1600; ++i) {
    if (word(r, i, "hit") != 1) continue;
    ++hits;
    const uint32_t p = word(r, i, "primitive_id"), x = i % 40;
    const uint32_t expect = (p & 1) && x < 20 ? 7 : p * 3 + x % 5;
    EXPECT_EQ(word(r, i, "value"), expect) << i;
  }
  EXPECT_GT(hits, 100);
}

TEST(Model, FacingCullsFlipAndDisable) {
  Ray up = downRay(0.5f, -0.5f, -5); up.direction = {0, 0, 1};
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
    Case c = baseCase({quad()}, {downRay(0.5f, -0.5f), downRay(0.5f, -0.5f), downRay(0.5f, -0.5f), downRay(0.5f, -0.5f)});
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
    Stmt far; far.kind = Stmt::Kind::Report; far.t = op("sphere_far", {}); far.hit_kind = lit(2);
    far.then_ = {count("far_accepted")};
    Stmt near = far; near.t = op("sphere_near", {}); near.hit_kind = lit(1);
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
  Case c = baseCase({g}, {downRay(0.5f, 0), downRay(1.0f, 0), downRay(1.0f + 1e-7f, 0), downRay(1.5f, 0)});
  Stmt rep; rep.kind = Stmt::Kind::Report; rep.t = litf(4.5); rep.hit_kind = lit(3);  // always reports
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
  Stmt rep; rep.kind = Stmt::Kind::Report; rep.t = litf(1.0); rep.hit_kind = lit(0);
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
  Stmt call; call.kind = Stmt::Kind::Call; call.call_index = lit(1);
  call.assigns = {{"value", lit(41)}};
  c.pipeline.hit_groups[0].closest_hit = Program{call, recordExpr("value", bi("callee.value"))};
  Stmt set; set.kind = Stmt::Kind::SetCall; set.assigns = {{"value", op("add", {bi("call.value"), lit(1)})}};
  c.pipeline.callables = {{count("calls")}, {count("calls"), set}};
  Results r = run(c, ModelTier::Exact);
  EXPECT_EQ(word(r, 0, "value"), 42u);
  EXPECT_EQ(word(r, 0, "callable_runs"), 1u);
  EXPECT_EQ(r.counters["calls"], 1u);
}

TEST(Model, PointLightFormula) {
  Case c = baseCase({quad()}, {downRay(0.5f, -0.5f)});
  Stmt call; call.kind = Stmt::Kind::Call; call.call_index = lit(0);
  call.assigns = {{"position", bi("hit_position")}, {"normal", vec3(0, 0, 1)}};
  c.pipeline.hit_groups[0].closest_hit = Program{call, recordExpr("color", bi("callee.color"))};
  Stmt light; light.kind = Stmt::Kind::Light; light.light = "point";
  c.pipeline.callables = {{light}};
  auto bits = [](float f) { uint32_t u; std::memcpy(&u, &f, 4); return u; };
  c.pipeline.sbt_callable = {{0, {bits(0.5f), bits(-0.5f), bits(2.0f), bits(1.0f), bits(0.5f), bits(0.25f)}}};
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
  c.pipeline.max_recursion = 1;
  r = run(c, ModelTier::Exact);
  EXPECT_EQ(r.status, RunStatus::Crash) << r.statusText();
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
  c.pipeline.hit_groups[0].any_hit =
      Program{count("anyhit"), ifThen(op("odd", {bi("primitive_id")}), {count("ignored"), simple(Stmt::Kind::Ignore)})};
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

// ---- R-TIE, R-ORDER-UNSPEC, R-TOFH: ties and first hits -------------------

std::map<uint32_t, const RayAmbiguity*> byRay(const Results& r) {
  std::map<uint32_t, const RayAmbiguity*> m;
  for (const RayAmbiguity& a : r.ambiguous) m[a.ray] = &a;
  return m;
}

// The legal hit answers of an ambiguous ray as (instance, geometry, primitive); miss: {~0u, ~0u, ~0u}.
std::set<std::array<uint32_t, 3>> legal(const RayAmbiguity& a) {
  std::set<std::array<uint32_t, 3>> s;
  for (const Candidate& k : a.candidates)
    s.insert(k.hit ? std::array<uint32_t, 3>{k.instance, k.geometry, k.primitive}
                   : std::array<uint32_t, 3>{~0u, ~0u, ~0u});
  return s;
}

std::array<uint32_t, 3> answer(const Results& r, uint32_t ray) {
  if (word(r, ray, "hit") != 1) return {~0u, ~0u, ~0u};
  return {word(r, ray, "instance_id"), word(r, ray, "geometry_index"), word(r, ray, "primitive_id")};
}

Geometry boxes(std::vector<std::array<float, 6>> aabbs, uint32_t flags = kGeometryOpaque) {
  Geometry g;
  g.kind = Geometry::Kind::Aabbs;
  g.aabbs = std::move(aabbs);
  g.flags = flags;
  return g;
}

// Three coincident boxes in two coincident instances, each report at t = 4:
// any of the six (instance, primitive) pairs may end as the closest hit.
TEST(ModelTies, CoincidentAabbsInDifferentInstancesAreATie) {
  const std::array<float, 6> box = {-1, -1, -1, 1, 1, 1};
  Case c = baseCase({boxes({box, box, box})}, {downRay(0, 0), downRay(0.5f, 0.25f), downRay(3, 3)});
  c.scene.instances.push_back(c.scene.instances[0]);
  Stmt rep; rep.kind = Stmt::Kind::Report; rep.t = litf(4.0); rep.hit_kind = lit(1);
  c.pipeline.hit_groups[0].intersection = Program{rep};
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  auto amb = byRay(r);
  for (uint32_t ray : {0u, 1u}) {
    ASSERT_EQ(amb.count(ray), 1u) << ray;
    EXPECT_EQ(amb[ray]->reason, AmbiguityReason::TTie);
    std::set<std::array<uint32_t, 3>> want;
    for (uint32_t i = 0; i < 2; ++i)
      for (uint32_t p = 0; p < 3; ++p) want.insert({i, 0, p});
    EXPECT_EQ(legal(*amb[ray]), want) << ray;
    EXPECT_TRUE(want.count(answer(r, ray))) << "the model's own answer is legal";
    EXPECT_NEAR(fword(r, ray, "hit_t"), 4.0f, 0);
    // What-if runs leave no trace: each box's program ran once in the record.
    EXPECT_EQ(word(r, ray, "intersection_runs"), 6u);
    EXPECT_EQ(word(r, ray, "closest_hit_runs"), 1u);
  }
  EXPECT_EQ(amb.count(2), 0u);  // a miss far from the boxes is clear
  EXPECT_EQ(r.counters["closesthit"], 2u);
  EXPECT_EQ(r.counters["miss"], 1u);
  for (ModelTier tier : {ModelTier::Fast, ModelTier::Robust}) {
    Results f = run(c, tier);
    EXPECT_TRUE(f.ambiguous.empty()) << modelTierName(tier);
    EXPECT_EQ(word(f, 0, "hit"), 1u);
  }
}

// An any-hit that ignores odd primitives: only the even ones are legal.
TEST(ModelTies, TieAnswersFollowAnyHit) {
  const std::array<float, 6> box = {-1, -1, -1, 1, 1, 1};
  Case c = baseCase({boxes({box, box, box, box}, 0)}, {downRay(0, 0)});
  c.scene.instances.push_back(c.scene.instances[0]);
  Stmt rep; rep.kind = Stmt::Kind::Report; rep.t = litf(4.0); rep.hit_kind = lit(1);
  c.pipeline.hit_groups[0].intersection = Program{rep};
  c.pipeline.hit_groups[0].any_hit =
      Program{count("anyhit"), ifThen(op("odd", {bi("primitive_id")}), {count("ignored"), simple(Stmt::Kind::Ignore)})};
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(r.ambiguous[0].reason, AmbiguityReason::TTie);
  const std::set<std::array<uint32_t, 3>> want = {{0, 0, 0}, {0, 0, 2}, {1, 0, 0}, {1, 0, 2}};
  EXPECT_EQ(legal(r.ambiguous[0]), want);
  EXPECT_TRUE(want.count(answer(r, 0)));
  EXPECT_EQ(r.counters["ignored"], 4u);  // the actual run only: 4 odd boxes
}

// Boxes at different depths (sphere reports at t = 4 and 7) are no tie.
TEST(ModelTies, DistinctReportsAreClear) {
  Case c = baseCase({boxes({{-1, -1, -4, 1, 1, -2}, {-1, -1, -1, 1, 1, 1}})}, {downRay(0, 0), downRay(0.1f, 0.2f)});
  c.scene.instances.push_back(c.scene.instances[0]);
  c.scene.instances[1].transform[3] = 10;  // second instance out of the rays' way
  Stmt rep; rep.kind = Stmt::Kind::Report; rep.t = op("sphere_near", {}); rep.hit_kind = lit(1);
  c.pipeline.hit_groups[0].intersection = Program{ifThen(op("sphere_hit", {}), {rep})};
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  EXPECT_TRUE(r.ambiguous.empty());
  for (uint32_t ray : {0u, 1u}) {
    EXPECT_EQ(answer(r, ray), (std::array<uint32_t, 3>{0, 0, 1})) << ray;
    EXPECT_NEAR(fword(r, ray, "hit_t"), ray == 0 ? 4.0f : 4.0f + (1 - std::sqrt(1 - 0.05f)), 1e-5);
  }
}

// Coplanar triangles in two coincident instances meet the ray at the same t.
TEST(ModelTies, CoplanarTrianglesInDifferentInstancesAreATie) {
  Case c = baseCase({quad()}, {downRay(0.5f, -0.5f), downRay(3, 3)});
  c.scene.instances.push_back(c.scene.instances[0]);
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  auto amb = byRay(r);
  ASSERT_EQ(amb.count(0), 1u);
  EXPECT_EQ(amb[0]->reason, AmbiguityReason::TTie);
  EXPECT_EQ(legal(*amb[0]), (std::set<std::array<uint32_t, 3>>{{0, 0, 0}, {1, 0, 0}}));
  EXPECT_EQ(amb.count(1), 0u);
  EXPECT_TRUE(run(c, ModelTier::Robust).ambiguous.empty());
}

// R-TOFH: two stacked quads; with TerminateOnFirstHit either may be
// confirmed first, so both are legal; without the flag the near one is clear.
TEST(ModelTies, TerminateOnFirstHitAllowsEveryConfirmableCandidate) {
  Ray tofh = downRay(0.5f, -0.5f);
  tofh.flags = kRayTerminateOnFirstHit;
  tofh.sbt_stride = 0;  // every geometry uses hit group 0
  Case c = baseCase({quad(0), quad(-1)}, {downRay(0.5f, -0.5f), tofh});
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  auto amb = byRay(r);
  EXPECT_EQ(amb.count(0), 0u);
  EXPECT_EQ(answer(r, 0), (std::array<uint32_t, 3>{0, 0, 0}));
  ASSERT_EQ(amb.count(1), 1u);
  EXPECT_EQ(amb[1]->reason, AmbiguityReason::FirstHit);
  EXPECT_EQ(legal(*amb[1]), (std::set<std::array<uint32_t, 3>>{{0, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(answer(r, 1), (std::array<uint32_t, 3>{0, 0, 0}));  // the model's order: nearest first
  EXPECT_EQ(r.counters["closesthit"], 2u);

  // An any-hit that ignores geometry 0: whatever comes first, only geometry 1
  // can be confirmed, so the ray is clear.
  Case q = baseCase({quad(0, 0), quad(-1, 0)}, {tofh});
  q.pipeline.hit_groups[0].any_hit =
      Program{ifThen(op("eq", {bi("geometry_index"), lit(0)}), {simple(Stmt::Kind::Ignore)})};
  Results rq = run(q, ModelTier::Exact);
  ASSERT_EQ(rq.statusText(), "ok");
  EXPECT_TRUE(rq.ambiguous.empty());
  EXPECT_EQ(answer(rq, 0), (std::array<uint32_t, 3>{0, 1, 0}));
  for (ModelTier tier : {ModelTier::Fast, ModelTier::Robust}) EXPECT_TRUE(run(c, tier).ambiguous.empty());
}

TEST(Model, TriangleIntervalIsOpen) {
  for (ModelTier tier : kTiers) {
    Ray a = downRay(0.5f, -0.5f); a.tmax = 5;    // hit exactly at tmax: no
    Ray b = downRay(0.5f, -0.5f); b.tmin = 5;    // exactly at tmin: no
    Ray d = downRay(0.5f, -0.5f); d.tmax = 5.001f;
    Case c = baseCase({quad()}, {a, b, d});
    Results r = run(c, tier);
    EXPECT_EQ(word(r, 0, "hit"), 0u) << modelTierName(tier);
    EXPECT_EQ(word(r, 1, "hit"), 0u) << modelTierName(tier);
    EXPECT_EQ(word(r, 2, "hit"), 1u) << modelTierName(tier);
    // Exact tier: at either end a float ray test may land a step inside, so
    // hit and miss are both legal there; the ray a little past is clear.
    auto amb = byRay(r);
    EXPECT_EQ(amb.count(2), 0u);
    if (tier != ModelTier::Exact) {
      EXPECT_TRUE(r.ambiguous.empty());
      continue;
    }
    const std::set<std::array<uint32_t, 3>> both = {{~0u, ~0u, ~0u}, {0, 0, 0}};
    ASSERT_EQ(amb.count(0), 1u);
    EXPECT_EQ(amb[0]->reason, AmbiguityReason::TmaxTie);
    EXPECT_EQ(legal(*amb[0]), both);
    ASSERT_EQ(amb.count(1), 1u);
    EXPECT_EQ(amb[1]->reason, AmbiguityReason::TminTie);
    EXPECT_EQ(legal(*amb[1]), both);
  }
}

TEST(Model, NanInYTriangleStaysActiveAndHugeTrianglesAreHit) {
  std::array<Vec3, 3> nanY = {Vec3{0, NAN, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  std::array<Vec3, 3> nanX = {Vec3{NAN, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  EXPECT_FALSE(triangleInactive(nanY));
  EXPECT_TRUE(needsOwnTriangleTest(nanY));
  EXPECT_TRUE(triangleInactive(nanX));
  for (ModelTier tier : kTiers) {
    Geometry g;
    g.flags = kGeometryOpaque;
    // primitive 0: NaN in Y (active, Embree would drop it); 1: a normal triangle;
    // 2: huge (beyond Embree's 1.8e18 limit) far below.
    g.vertices = {{10, NAN, 0}, {11, 0, 0}, {10, 1, 0},
                  {-1, -1, 0}, {1, -1, 0}, {1, 1, 0},
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

TEST(Model, ImagesFollowTheRecord) {
  Case c = baseCase({quad()}, {downRay(0.5f, -0.5f), downRay(3, 3)}, 2);
  c.outputs.images = {{"prim", "primitive_id", {}}, {"t", "hit_t", {}}};
  Results r = run(c, ModelTier::Fast);
  ASSERT_EQ(r.images.size(), 2u);
  EXPECT_FALSE(r.images[0].is_float);
  EXPECT_EQ(r.images[0].channels, 1u);
  EXPECT_TRUE(r.images[1].is_float);
  ASSERT_EQ(r.images[1].texels.size(), 8u);
  float t, a;
  std::memcpy(&t, &r.images[1].texels[0], 4);
  std::memcpy(&a, &r.images[1].texels[3], 4);
  EXPECT_NEAR(t, 5.0f, 1e-5);
  EXPECT_EQ(a, 1.0f);
  EXPECT_EQ(r.images[1].texels[1], 0u);
}

// ---- R-PREC: sphere decisions near rounding ("shader-arith") ---------------

// A sphere of radius 1 at the origin inscribed in a flat box (its x/y faces
// far from the rays below), the usual far-then-near reports.
Case sphereCase(std::vector<Ray> rays) {
  Geometry g;
  g.kind = Geometry::Kind::Aabbs;
  g.aabbs = {{-2, -2, -1, 2, 2, 1}};
  g.flags = kGeometryOpaque;
  Case c = baseCase({g}, std::move(rays));
  Stmt far; far.kind = Stmt::Kind::Report; far.t = op("sphere_far", {}); far.hit_kind = lit(2);
  far.then_ = {count("far_accepted")};
  Stmt near = far; near.t = op("sphere_near", {}); near.hit_kind = lit(1);
  near.then_ = {count("near_accepted")};
  c.pipeline.hit_groups[0].intersection = Program{ifThen(op("sphere_hit", {}), {far, near})};
  return c;
}

TEST(ModelSphere, TangentRayIsAmbiguousWithBothAnswers) {
  // 0: exactly tangent (disc == 0), 1: clearly through, 2: clearly missing
  // (inside the box), 3: a hair inside the tangent line.
  Case c = sphereCase({downRay(1.0f, 0), downRay(0.5f, 0), downRay(1.5f, 0), downRay(0.9999999f, 0)});
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  std::map<uint32_t, const RayAmbiguity*> amb;
  for (const RayAmbiguity& a : r.ambiguous) amb[a.ray] = &a;
  EXPECT_EQ(word(r, 1, "hit"), 1u);
  EXPECT_EQ(word(r, 2, "hit"), 0u);
  EXPECT_EQ(amb.count(1), 0u);
  EXPECT_EQ(amb.count(2), 0u);
  EXPECT_EQ(word(r, 0, "intersection_runs"), 1u);
  for (uint32_t ray : {0u, 3u}) {
    ASSERT_EQ(amb.count(ray), 1u) << ray;
    EXPECT_EQ(amb[ray]->reason, AmbiguityReason::ShaderArith) << ray;
    bool hit = false, miss = false;
    for (const Candidate& k : amb[ray]->candidates) {
      (k.hit ? hit : miss) = true;
      if (k.hit) { EXPECT_EQ(k.primitive, 0u); }
    }
    EXPECT_TRUE(hit && miss) << ray;
  }
  // The fast and robust tiers mark nothing.
  for (ModelTier tier : {ModelTier::Fast, ModelTier::Robust}) EXPECT_TRUE(run(c, tier).ambiguous.empty());
  // The sandboxed what-if runs left the actual run's counters alone: the
  // model hits rays 0 (disc exactly 0), 1 and 3 once each.
  EXPECT_EQ(r.counters["far_accepted"], 3u);
  EXPECT_EQ(r.counters["near_accepted"], 3u);
  EXPECT_EQ(r.counters["closesthit"], 3u);
}

TEST(ModelSphere, NearlyTangentHitGetsAWiderTBoundThanACentralHit) {
  // 0: through the centre (disc large), 1: close to tangency but clearly
  // inside (disc small, so sqrt amplifies a device's rounding).
  Case c = sphereCase({downRay(0.0f, 0), downRay(0.999f, 0)});
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  EXPECT_EQ(word(r, 0, "hit"), 1u);
  EXPECT_EQ(word(r, 1, "hit"), 1u);
  std::map<uint32_t, float> bound;
  for (const TBound& b : r.t_bounds) bound[b.ray] = b.bound;
  ASSERT_EQ(bound.count(1), 1u) << "a near-tangent root needs more than the default tolerance";
  EXPECT_GT(bound[1], 1e-4f);
  if (bound.count(0)) EXPECT_LT(bound[0], bound[1]);
  EXPECT_TRUE(run(c, ModelTier::Fast).t_bounds.empty()) << "only the exact tier bounds t";
}

TEST(ModelSphere, RootNearTminIsAmbiguous) {
  // The ray starts just below the sphere (z = -1) going up: its near root is
  // ~tmin (0.001), its far root clear.
  Ray onSurface = downRay(0, 0, -1.001f);
  onSurface.direction = {0, 0, 1};
  Ray clear = downRay(0, 0, 0);  // from the centre: far root 1, clear
  Case c = sphereCase({onSurface, clear});
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  std::map<uint32_t, const RayAmbiguity*> amb;
  for (const RayAmbiguity& a : r.ambiguous) amb[a.ray] = &a;
  EXPECT_EQ(amb.count(1), 0u);
  EXPECT_EQ(word(r, 1, "hit"), 1u);
  EXPECT_NEAR(fword(r, 1, "hit_t"), 1.0f, 1e-6);
  ASSERT_EQ(amb.count(0), 1u);
  EXPECT_EQ(amb[0]->reason, AmbiguityReason::ShaderArith);
  EXPECT_EQ(word(r, 0, "hit"), 1u);
}

TEST(ModelSphere, ErrorBoundsAreTightForClearRays) {
  const std::array<float, 12> identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  const F3 bmin = {-1, -1, -1}, bmax = {1, 1, 1};
  const F3 o = {0.5f, 0, 5}, d = {0, 0, -1};
  const SphereError se = sphereError(bmin, bmax, o, d, objectRayError(identity, o, d));
  EXPECT_NEAR(se.disc, 0.75, 1e-9);
  EXPECT_GT(se.disc_err, 0.0);
  EXPECT_LT(se.disc_err, 1e-5 * 25);  // b * b = 25: conservative, not silly
  EXPECT_LT(se.near_err, 2e-4);
  EXPECT_LT(se.far_err, 2e-4);
  // A translation adds the rounding of its larger magnitudes.
  const std::array<float, 12> moved = {1, 0, 0, -1000, 0, 1, 0, 0, 0, 0, 1, 0};
  EXPECT_GT(objectRayError(moved, o, d).origin[0], objectRayError(identity, o, d).origin[0]);
}

// The finding on the NVIDIA H200: mixed-scene-1024 ray 638477 (x=525,
// y=623) grazes a ball; the model's numbers for that ray, and its verdict.
TEST(ModelSphere, MixedSceneRay638477IsTangent) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(RAYSPEC_SOURCE_DIR) / "cases";
  ParseResult p = parseCaseFile((root / "model/mixed-scene-1024.yaml").string(), root.string());
  ASSERT_TRUE(p.value);
  Case c = *p.value;
  const uint32_t index = 638477;
  ASSERT_GT(c.rays.rays.size(), index);
  const Ray ray = c.rays.rays[index];
  ModelScene scene;
  buildModelScene(scene, c, ModelTier::Exact, true);
  const ModelInstance& mi = scene.instances[1];
  const auto& aabbs = c.scene.blases[mi.blas].geometries[0].aabbs;
  bool tangent = false;
  for (size_t k = 0; k < aabbs.size(); ++k) {
    const auto& bx = aabbs[k];
    const F3 bmin = {bx[0], bx[1], bx[2]}, bmax = {bx[3], bx[4], bx[5]};
    F3 of, df;
    double od[3], dd[3];
    for (int i = 0; i < 3; ++i) {
      of[i] = mi.inverse_f[i * 4] * ray.origin[0] + mi.inverse_f[i * 4 + 1] * ray.origin[1] +
              mi.inverse_f[i * 4 + 2] * ray.origin[2] + mi.inverse_f[i * 4 + 3];
      df[i] = mi.inverse_f[i * 4] * ray.direction[0] + mi.inverse_f[i * 4 + 1] * ray.direction[1] +
              mi.inverse_f[i * 4 + 2] * ray.direction[2];
      od[i] = mi.inverse[i * 4] * ray.origin[0] + mi.inverse[i * 4 + 1] * ray.origin[1] +
              mi.inverse[i * 4 + 2] * ray.origin[2] + mi.inverse[i * 4 + 3];
      dd[i] = mi.inverse[i * 4] * ray.direction[0] + mi.inverse[i * 4 + 1] * ray.direction[1] +
              mi.inverse[i * 4 + 2] * ray.direction[2];
    }
    // Float, operation by operation (sphereRoots), and double.
    F3 cf, hf;
    double cd[3], hd[3];
    for (int i = 0; i < 3; ++i) {
      cf[i] = (bmin[i] + bmax[i]) * 0.5f; hf[i] = (bmax[i] - bmin[i]) * 0.5f;
      cd[i] = (double(bmin[i]) + bmax[i]) * 0.5; hd[i] = (double(bmax[i]) - bmin[i]) * 0.5;
    }
    const float rf = std::min({hf[0], hf[1], hf[2]});
    const double rd = std::min({hd[0], hd[1], hd[2]});
    float af = 0, bf = 0, ccf = 0;
    double ad = 0, bd = 0, ccd = 0;
    const F3 ocf = {of[0] - cf[0], of[1] - cf[1], of[2] - cf[2]};
    af = df[0] * df[0] + df[1] * df[1] + df[2] * df[2];
    bf = ocf[0] * df[0] + ocf[1] * df[1] + ocf[2] * df[2];
    ccf = ocf[0] * ocf[0] + ocf[1] * ocf[1] + ocf[2] * ocf[2] - rf * rf;
    for (int i = 0; i < 3; ++i) {
      const double oc = od[i] - cd[i];
      ad += dd[i] * dd[i]; bd += oc * dd[i]; ccd += oc * oc;
    }
    ccd -= rd * rd;
    const float discf = bf * bf - af * ccf;
    const double discd = bd * bd - ad * ccd;
    const SphereRoots sr = sphereRoots(bmin, bmax, of, df);
    EXPECT_EQ(sr.disc, discf);
    const SphereError se = sphereError(bmin, bmax, of, df, objectRayError(mi.inverse_f, ray.origin, ray.direction));
    const double sd = std::sqrt(std::max(discd, 0.0));
    std::printf("ray %u box %zu: float a=%.9g b=%.9g cc=%.9g disc=%.9g near=%.9g far=%.9g\n", index, k, af, bf, ccf,
                discf, sr.t_near, sr.t_far);
    std::printf("ray %u box %zu: double a=%.17g b=%.17g cc=%.17g disc=%.17g near=%.17g far=%.17g\n", index, k, ad,
                bd, ccd, discd, (-bd - sd) / ad, (-bd + sd) / ad);
    std::printf("ray %u box %zu: bound disc_err=%.3g near_err=%.3g far_err=%.3g\n", index, k, se.disc_err,
                se.near_err, se.far_err);
    if (std::fabs(double(discf)) <= se.disc_err) tangent = true;
  }
  EXPECT_TRUE(tangent);
  // The exact tier marks that ray alone ambiguous, with a hit and the other path legal.
  c.rays.rays = {ray};
  c.rays.width = c.rays.height = 1;
  const Plan plan = derivePlan(c);
  Results r = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(r.ambiguous[0].reason, AmbiguityReason::ShaderArith);
  EXPECT_GE(r.ambiguous[0].candidates.size(), 2u);
  for (const Candidate& k : r.ambiguous[0].candidates)
    std::printf("legal: hit=%d instance=%u geometry=%u primitive=%u\n", k.hit, k.instance, k.geometry, k.primitive);
}

TEST(Model, EveryCaseFileRunsInEveryTier) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(RAYSPEC_SOURCE_DIR) / "cases";
  int ran = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".yaml") continue;
    ParseResult p = parseCaseFile(entry.path().string(), root.string());
    if (!p.value) {
      std::cerr << "skipping " << entry.path() << ": " << (p.errors.empty() ? "" : p.errors[0].format()) << "\n";
      continue;
    }
    const Case& c = *p.value;
    const Plan plan = derivePlan(c);
    std::vector<uint32_t> fastRecords;
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
      const bool oneTrace = !plan.nested_trace && c.pipeline.raygen.size() == 1 &&
                            c.pipeline.raygen[0].kind == Stmt::Kind::Trace;
      for (uint32_t i = 0; i < c.rays.width * c.rays.height && oneTrace; ++i)
        EXPECT_LE(word(r, i, "closest_hit_runs") + word(r, i, "miss_runs"), 1u) << c.name << " ray " << i;
      if (tier != ModelTier::Exact) continue;
      // Rays the exact tier calls clear agree with the fast tier.
      if (fastRecords.empty()) {
        fastRecords = runOnModel(c, plan, ModelOptions{ModelTier::Fast, 1}).records;
        std::vector<bool> amb(c.rays.width * c.rays.height, false);
        for (const RayAmbiguity& a : r.ambiguous) amb[a.ray] = true;
        uint32_t differ = 0;
        const uint32_t words = recordWords();
        for (uint32_t i = 0; i < c.rays.width * c.rays.height; ++i) {
          if (amb[i]) continue;
          if (word(r, i, "hit") != fastRecords[i * words + findRecordField("hit")->offset] ||
              word(r, i, "primitive_id") != fastRecords[i * words + findRecordField("primitive_id")->offset])
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
