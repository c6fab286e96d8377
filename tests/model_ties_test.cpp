// The model's ties and first hits (R-TIE, R-ORDER-UNSPEC, R-TOFH): which
// answers the exact tier lists as legal.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <set>

#include "model_support.h"

namespace rayspec {
namespace {

using namespace model_test;

// Three coincident boxes in two coincident instances, each report at t = 4:
// any of the six (instance, primitive) pairs may end as the closest hit.
TEST(ModelTies, CoincidentAabbsInDifferentInstancesAreATie) {
  const std::array<float, 6> box = {-1, -1, -1, 1, 1, 1};
  Case c = baseCase({boxes({box, box, box})}, {downRay(0, 0), downRay(0.5f, 0.25f), downRay(3, 3)});
  c.scene.instances.push_back(c.scene.instances[0]);
  Stmt rep;
  rep.kind = Stmt::Kind::Report;
  rep.t = litf(4.0);
  rep.hit_kind = lit(1);
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
  Stmt rep;
  rep.kind = Stmt::Kind::Report;
  rep.t = litf(4.0);
  rep.hit_kind = lit(1);
  c.pipeline.hit_groups[0].intersection = Program{rep};
  c.pipeline.hit_groups[0].any_hit = Program{
      count("anyhit"),
      ifThen(op("odd", {bi("primitive_id")}), {count("ignored"), simple(Stmt::Kind::Ignore)})};
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
  Case c = baseCase({boxes({{-1, -1, -4, 1, 1, -2}, {-1, -1, -1, 1, 1, 1}})},
                    {downRay(0, 0), downRay(0.1f, 0.2f)});
  c.scene.instances.push_back(c.scene.instances[0]);
  c.scene.instances[1].transform[3] = 10;  // second instance out of the rays' way
  Stmt rep;
  rep.kind = Stmt::Kind::Report;
  rep.t = op("sphere_near", {});
  rep.hit_kind = lit(1);
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
  for (ModelTier tier : {ModelTier::Fast, ModelTier::Robust})
    EXPECT_TRUE(run(c, tier).ambiguous.empty());
}

// A tie behind a leak (fuzz seed 160964 on NVIDIA): the ray passes exactly
// through a border vertex of a triangle at z = 2 (hit or miss, both legal),
// then meets one triangle given twice, in both windings, at z = 0, no
// culling: where the vertex is missed, either twin is the closest hit
// (R-TIE), not only the one the model's tie rule keeps.
TEST(ModelTies, ATieBehindAMissedVertexListsEveryTwin) {
  Case c = parseInline(R"(rules: [R-WATERTIGHT, R-TIE]
scene:
  blas:
    corner:
      - triangles:
          vertices: [[0, 0, 2], [1, 0, 2], [0, 1, 2]]
        flags: [opaque]
    twins:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
          indices: [0, 1, 2, 0, 2, 1]
        flags: [opaque]
  instances: [{blas: corner}, {blas: twins}]
rays:
  list:
    - {origin: [0, 0, 5], direction: [0, 0, -1]}
pipeline:
  raygen: [trace: {}]
  miss: [[count: miss]]
  hit_groups:
    - closest_hit: [{count: closesthit}, {record: [hit, instance_id, geometry_index, primitive_id]}]
outputs:
  counters: [miss, closesthit]
  per_ray: [hit, instance_id, geometry_index, primitive_id]
)");
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  auto amb = byRay(r);
  ASSERT_EQ(amb.count(0), 1u);
  const std::set<std::array<uint32_t, 3>> got = legal(*amb[0]);
  EXPECT_TRUE(got.count({1, 0, 0})) << "twin 0 behind the vertex";
  EXPECT_TRUE(got.count({1, 0, 1})) << "twin 1 behind the vertex";
  EXPECT_TRUE(got.count({0, 0, 0})) << "the vertex's triangle";
  EXPECT_TRUE(got.count(answer(r, 0))) << "the model's own answer is legal";
}

}  // namespace
}  // namespace rayspec
