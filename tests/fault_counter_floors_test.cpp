// The floor of a counter that intersection or any-hit programs count
// (Results::counter_floors, model/counter_floors.cpp): a device that runs
// fewer programs than every legal order offers before the committed hit
// fails; one that runs them once or again passes; a candidate beyond the
// committed hit (offered in some orders only) raises no floor.
#include <gtest/gtest.h>

#include <algorithm>

#include "compare/compare_results.h"
#include "model/model_engine.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// Boxes of the unit cube's size along x at the given centres, one ray along
// +x from x = -5; the intersection program counts, then reports its sphere's
// near root (or nothing), and the closest-hit records the primitive.
std::string boxesText(const std::string& aabbs, const std::string& intersection) {
  return "rules: [R-AABB-CONS, R-ORDER-UNSPEC]\n"
         "description: floors\n"
         "scene:\n"
         "  blas:\n"
         "    b: [{aabbs: " +
         aabbs +
         ", flags: [opaque]}]\n"
         "  instances: [{blas: b}]\n"
         "rays:\n"
         "  list: [{origin: [-5, 0.125, 0.0625], direction: [1, 0, 0]}]\n"
         "  tmin: 0.001\n"
         "  tmax: 100\n"
         "pipeline:\n"
         "  miss: [[count: miss, record: {hit: 0}]]\n"
         "  hit_groups:\n"
         "    - intersection: " +
         intersection +
         "\n"
         "      closest_hit: [count: chit, record: [hit, primitive_id]]\n"
         "outputs:\n"
         "  counters: [isect, miss, chit]\n"
         "  per_ray: [hit, primitive_id]\n";
}

Case parsed(const std::string& text) {
  ParseResult p = parseCaseText(text, "t.yaml", "t/t");
  EXPECT_TRUE(p.value.has_value()) << (p.errors.empty() ? "" : p.errors[0].message);
  return p.value ? *p.value : Case{};
}

// The model's results as a device that ran the intersection program `runs`
// times on its one ray (its records agree).
Results deviceRunning(const Results& model, uint32_t runs) {
  Results d = model;
  d.backend = "vulkan";
  d.counter_floors.clear();
  d.counters["isect"] = runs;
  d.records[findRecordField("intersection_runs")->offset] = runs;
  return d;
}

Status verdictOf(const Case& c, const Results& model, uint32_t runs, std::string* headline) {
  const Verdict v = compareResults(c, derivePlan(c), deviceRunning(model, runs), model);
  *headline = v.headline();
  return v.status;
}

const char* kReports =
    "[count: isect, {if: sphere_hit, then: [report: {t: {max: [sphere_near, ray_tmin]}, kind: "
    "1}]}]";

TEST(CounterFloors, ABoxClearlyInRangeRunsItsIntersectionProgram) {
  const Case c = parsed(boxesText("[[-1, -1, -1, 1, 1, 1]]", "[count: isect]"));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_TRUE(model.ok()) << model.statusText();
  ASSERT_EQ(model.counters.at("isect"), 1u);
  ASSERT_EQ(model.counter_floors.at("isect"), 1u);
  std::string h;
  EXPECT_EQ(verdictOf(c, model, 0, &h), Status::Fail) << h;
  EXPECT_NE(h.find("R-AABB-CONS"), std::string::npos) << h;
  EXPECT_NE(h.find("device 0, at least 1"), std::string::npos) << h;
  EXPECT_EQ(verdictOf(c, model, 1, &h), Status::Pass) << h;
  EXPECT_EQ(verdictOf(c, model, 2, &h), Status::Pass) << h;  // R-ISECT-MULTI: again
}

TEST(CounterFloors, ABoxBeyondTheCommittedHitRaisesNoFloor) {
  // The near box reports t = 4; the far box is entered at t = 8, beyond it:
  // an order offering it first runs its program, the model's does not.
  const Case c = parsed(boxesText("[[-1, -1, -1, 1, 1, 1], [3, -1, -1, 5, 1, 1]]", kReports));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_TRUE(model.ok()) << model.statusText();
  ASSERT_EQ(model.counters.at("isect"), 1u);
  EXPECT_EQ(model.counter_floors.at("isect"), 1u) << "the near box only";
  std::string h;
  EXPECT_EQ(verdictOf(c, model, 0, &h), Status::Fail) << h;
  EXPECT_EQ(verdictOf(c, model, 1, &h), Status::Pass) << h;
  EXPECT_EQ(verdictOf(c, model, 2, &h), Status::Pass) << h;  // the far box too
}

TEST(CounterFloors, BoxesBeforeAMissAllRun) {
  // Reports nothing: the ray misses, every box it enters runs its program.
  const Case c =
      parsed(boxesText("[[-1, -1, -1, 1, 1, 1], [3, -1, -1, 5, 1, 1]]", "[count: isect]"));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_TRUE(model.ok()) << model.statusText();
  EXPECT_EQ(model.counter_floors.at("isect"), 2u);
  std::string h;
  EXPECT_EQ(verdictOf(c, model, 1, &h), Status::Fail) << h;
  EXPECT_EQ(verdictOf(c, model, 2, &h), Status::Pass) << h;
}

TEST(CounterFloors, ACountAfterAConditionRaisesNoFloor) {
  // Not the program's leading statement: how often it counts is not known.
  const Case c =
      parsed(boxesText("[[-1, -1, -1, 1, 1, 1]]", "[{if: sphere_hit, then: [count: isect]}]"));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_TRUE(model.ok()) << model.statusText();
  EXPECT_FALSE(model.counter_floors.count("isect"));
}

}  // namespace
}  // namespace rayspec
