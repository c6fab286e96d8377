#include <gtest/gtest.h>

#include "plan/plan.h"
#include "program/ops.h"

namespace rayspec {
namespace {

Geometry quad(uint32_t flags) {
  Geometry g;
  g.kind = Geometry::Kind::Triangles;
  g.flags = flags;
  g.vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  g.indices = {0, 1, 2, 0, 2, 3};
  return g;
}

Geometry box() {
  Geometry g;
  g.kind = Geometry::Kind::Aabbs;
  g.aabbs = {{-1, -1, -1, 1, 1, 1}};
  return g;
}

Stmt count(const std::string& name) {
  Stmt s;
  s.kind = Stmt::Kind::Count;
  s.counter = name;
  return s;
}

Case baseCase(Geometry g) {
  Case c;
  c.scene.blases.push_back({"b", {std::move(g)}, {}});
  Instance inst;
  inst.blas = 0;
  c.scene.instances.push_back(inst);
  c.rays.rays.push_back(Ray{});
  Stmt trace;
  trace.kind = Stmt::Kind::Trace;
  c.pipeline.raygen = {trace};
  c.pipeline.miss.push_back({count("miss")});
  HitGroup hg;
  hg.closest_hit = Program{count("chit")};
  c.pipeline.hit_groups.push_back(hg);
  c.outputs.counters = {"miss", "chit"};
  return c;
}

TEST(Plan, OpaqueTrianglesWithClosestHitNeedNothingElse) {
  const Plan p = derivePlan(baseCase(quad(kGeometryOpaque)));
  EXPECT_TRUE(p.triangles);
  EXPECT_FALSE(p.aabbs);
  EXPECT_FALSE(p.any_hit);
  EXPECT_FALSE(p.intersection);
  EXPECT_FALSE(p.callables);
  EXPECT_FALSE(p.nested_trace);
  EXPECT_EQ(p.trace_depth, 1u);
  EXPECT_FALSE(p.scene_data);
  EXPECT_FALSE(p.masks);
  EXPECT_FALSE(p.facing_culls);
  EXPECT_TRUE(p.images.empty());
  EXPECT_FALSE(p.records) << "a counters-only case keeps no per-ray records";
}

TEST(Plan, RecordsWhenPerRayFieldsOrImagesAreKept) {
  Case c = baseCase(quad(kGeometryOpaque));
  c.outputs.per_ray = {"hit"};
  EXPECT_TRUE(derivePlan(c).records);
  c.outputs.per_ray.clear();
  c.outputs.images.push_back({"hit", "hit", {}});
  EXPECT_TRUE(derivePlan(c).records);
}

TEST(Plan, AnyHitOnlyWhenSomeCandidateCanBeNonOpaque) {
  Case c = baseCase(quad(kGeometryOpaque));
  c.pipeline.hit_groups[0].any_hit = Program{count("ahit")};
  EXPECT_FALSE(derivePlan(c).any_hit) << "opaque geometry never runs any-hit";
  c.scene.instances[0].flags = kInstanceForceNoOpaque;
  EXPECT_TRUE(derivePlan(c).any_hit) << "force_no_opaque makes it non-opaque";

  Case d = baseCase(quad(0));
  d.pipeline.hit_groups[0].any_hit = Program{count("ahit")};
  EXPECT_TRUE(derivePlan(d).any_hit);
  d.rays.rays[0].flags = kRayOpaque;
  EXPECT_FALSE(derivePlan(d).any_hit) << "every ray forces opaque";
  d.scene.instances[0].flags = kInstanceForceOpaque;
  d.rays.rays[0].flags = 0;
  EXPECT_FALSE(derivePlan(d).any_hit) << "the instance forces opaque";
}

TEST(Plan, IntersectionAndSceneDataOnlyWithAabbs) {
  Case c = baseCase(box());
  Stmt report;
  report.kind = Stmt::Kind::Report;
  report.t.kind = Expr::Kind::Op;
  setOp(report.t, Op::SphereNear);
  c.pipeline.hit_groups[0].intersection = Program{report};
  Plan p = derivePlan(c);
  EXPECT_TRUE(p.aabbs);
  EXPECT_TRUE(p.intersection);
  EXPECT_TRUE(p.scene_data);
  EXPECT_FALSE(p.triangles);
  c.pipeline.flags = 0x2000;  // skip AABBs in the pipeline
  p = derivePlan(c);
  EXPECT_FALSE(p.aabbs);
  EXPECT_FALSE(p.intersection);
}

TEST(Plan, NullInstancesAndEmptyGeometryAddNothing) {
  Case c = baseCase(box());
  c.scene.instances[0].blas.reset();
  const Plan p = derivePlan(c);
  EXPECT_FALSE(p.aabbs);
  EXPECT_FALSE(p.triangles);
}

TEST(Plan, RecursionCallablesMasksAndCulls) {
  Case c = baseCase(quad(kGeometryOpaque));
  Stmt nested;
  nested.kind = Stmt::Kind::Trace;
  Stmt call;
  call.kind = Stmt::Kind::Call;
  c.pipeline.hit_groups[0].closest_hit->push_back(nested);
  c.pipeline.hit_groups[0].closest_hit->push_back(call);
  c.pipeline.max_recursion = 3;
  c.pipeline.callables.push_back({count("call")});
  c.rays.rays[0].cull_mask = 0x0F;
  c.rays.rays[0].flags = kRayCullBackFacing;
  const Plan p = derivePlan(c);
  EXPECT_TRUE(p.nested_trace);
  EXPECT_EQ(p.trace_depth, 3u);
  EXPECT_TRUE(p.callables);
  EXPECT_TRUE(p.masks);
  EXPECT_TRUE(p.facing_culls);
  EXPECT_FALSE(p.describe().empty());
}

}  // namespace
}  // namespace rayspec

namespace rayspec {
namespace {

// What the plan saves is measured against this (bench/plan_saving.cpp).
TEST(Plan, EveryEffectPlanSwitchesEverythingOn) {
  const Case c = baseCase(quad(kGeometryOpaque));
  const Plan derived = derivePlan(c), every = everyEffectPlan(c);
  EXPECT_FALSE(derived.any_hit);
  for (bool on : {every.triangles, every.aabbs, every.any_hit, every.intersection,
                  every.closest_hit, every.miss, every.callables, every.nested_trace,
                  every.facing_culls, every.masks, every.opacity_flags, every.scene_data,
                  every.shader_record_data, every.zero_records, every.records})
    EXPECT_TRUE(on);
  EXPECT_EQ(every.counters, derived.counters);
  EXPECT_GT(every.record_fields.size(), derived.record_fields.size());
  EXPECT_EQ(every.images.size(), every.record_fields.size());
}

}  // namespace
}  // namespace rayspec
