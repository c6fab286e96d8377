// The floor of a counter that intersection or any-hit programs or ray query
// blocks count (Results::counter_floors, model/counter_floors.cpp): a device
// that runs fewer programs than every legal order offers before the
// committed hit fails; one that runs them once or again passes; a candidate
// beyond the committed hit (offered in some orders only) raises no floor.
// The any-hit of a box's leading report and a query's candidate blocks are
// in it: the planted faults ignore-discards-writes and
// query-candidate-shrinks-interval are caught by the floor alone.
#include <gtest/gtest.h>

#include <algorithm>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "model/model_engine.h"
#include "parse/parse_case.h"
#include "plan/plan.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// Boxes along x (the blas's one geometry `geometry`), one ray along +x from
// x = -5; the intersection program `intersection` (then the hit group's
// `any_hit` line, if any), and the closest-hit records the primitive.
// `head`: the rules and description; `counters`: those the case counts.
std::string boxCaseText(const std::string& head, const std::string& geometry,
                        const std::string& intersection, const std::string& any_hit,
                        const std::string& counters) {
  return head +
         "scene:\n"
         "  blas:\n"
         "    b: [" +
         geometry +
         "]\n"
         "  instances: [{blas: b}]\n"
         "rays:\n"
         "  list: [{origin: [-5, 0.125, 0.0625], direction: [1, 0, 0]}]\n"
         "  tmin: 0.001\n"
         "  tmax: 100\n"
         "pipeline:\n"
         "  miss: [[count: miss, record: {hit: 0}]]\n"
         "  hit_groups:\n"
         "    - intersection: " +
         intersection + "\n" + any_hit +
         "      closest_hit: [count: chit, record: [hit, primitive_id]]\n"
         "outputs:\n"
         "  counters: [" +
         counters +
         "]\n"
         "  per_ray: [hit, primitive_id]\n";
}

// Opaque boxes of the unit cube's size along x at the given centres; the
// intersection program counts, then reports its sphere's near root (or
// nothing).
std::string boxesText(const std::string& aabbs, const std::string& intersection) {
  return boxCaseText("rules: [R-AABB-CONS, R-ORDER-UNSPEC]\ndescription: floors\n",
                     "{aabbs: " + aabbs + ", flags: [opaque]}", intersection, "",
                     "isect, miss, chit");
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

// Two non-opaque boxes along the ray (the near one reported at t 4, the far
// at t 8); each intersection program's leading statement after its count
// reports, and the any-hit counts, then ignores the near box's report.
std::string reportedBoxesText(const std::string& intersection) {
  return boxCaseText(
      "rules: [R-ISECT-REPORT, R-IGNORE]\ndescription: report floors\n",
      "{aabbs: [[-1, -1, -1, 1, 1, 1], [3, -1, -1, 5, 1, 1]], flags: []}", intersection,
      "      any_hit: [count: ahit, {if: {eq: [primitive_id, 0]}, then: [ignore]}]\n",
      "isect, ahit, miss, chit");
}

const char* kLeadingReport = "[count: isect, report: {t: {max: [sphere_near, ray_tmin]}, kind: 1}]";

// The device as the planted fault `name` makes it from the model's own answers.
Results planted(const std::string& name, const Case& c, const Results& model) {
  Results d = perfectDevice(c, model);
  const FaultResult f = plantFault(name, c, derivePlan(c), d, model);
  EXPECT_TRUE(f.applied) << f.what;
  return d;
}

TEST(CounterFloors, AnIgnoredReportBeforeTheCommittedHitRunsItsAnyHit) {
  const Case c = parsed(reportedBoxesText(kLeadingReport));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_TRUE(model.ok()) << model.statusText();
  ASSERT_EQ(model.counters.at("ahit"), 2u);
  // The near box's report (ignored) and the far box's (committed).
  EXPECT_EQ(model.counter_floors.at("ahit"), 2u);
  EXPECT_EQ(model.counter_floors.at("isect"), 2u);
  // Planted: the ignoring any-hit's count is lost; nothing else the case
  // compares changes (the records and the other counters agree).
  const Results d = planted("ignore-discards-writes", c, model);
  EXPECT_EQ(d.counters.at("ahit"), 1u);
  const Verdict v = compareResults(c, derivePlan(c), d, model);
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_NE(v.headline().find("R-ISECT-REPORT"), std::string::npos) << v.headline();
  EXPECT_NE(v.headline().find("counter 'ahit': device 1, at least 2"), std::string::npos)
      << v.headline();
}

TEST(CounterFloors, AReportThatReadsTheIntervalRaisesNoAnyHitFloor) {
  // Its t (ray_tmax, the committed t so far) depends on the order: only
  // the committed report's any-hit is sure.
  const Case c = parsed(reportedBoxesText(
      "[count: isect, report: {t: {min: [{max: [sphere_near, ray_tmin]}, ray_tmax]}, kind: 1}]"));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_TRUE(model.ok()) << model.statusText();
  EXPECT_EQ(model.counter_floors.at("ahit"), 1u);
}

TEST(CounterFloors, AConditionalReportRaisesNoAnyHitFloorButTheCommittedOne) {
  const Case c = parsed(reportedBoxesText(
      "[count: isect, {if: sphere_hit, then: [report: {t: {max: [sphere_near, ray_tmin]}, kind: "
      "1}]}]"));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_TRUE(model.ok()) << model.statusText();
  EXPECT_EQ(model.counter_floors.at("ahit"), 1u);
}

// Three non-opaque triangles along a ray query's ray; its triangle block
// counts each candidate and confirms none (`confirm`: confirms each).
std::string queryText(const std::string& block) {
  return "rules: [R-RQ-CANDIDATES]\n"
         "description: query floors\n"
         "scene:\n"
         "  blas:\n"
         "    tri: [{triangles: {vertices: [[-5, -5, 0], [5, -5, 0], [0, 5, 0]]}, flags: []}]\n"
         "  instances:\n"
         "    - {blas: tri}\n"
         "    - {blas: tri, transform: {translate: [0, 0, -1]}}\n"
         "    - {blas: tri, transform: {translate: [0, 0, -2]}}\n"
         "rays:\n"
         "  list: [{origin: [0.1, 0.2, 10], direction: [0, 0, -1]}]\n"
         "  tmin: 0.001\n"
         "  tmax: 100\n"
         "pipeline:\n"
         "  raygen:\n"
         "    - ray_query:\n"
         "        triangle: " +
         block +
         "\n"
         "        after: [record: {value: committed.type}]\n"
         "outputs:\n"
         "  counters: [candidates]\n"
         "  per_ray: [value]\n";
}

TEST(CounterFloors, AQueryOffersEveryCandidateBeforeItsCommittedHit) {
  const Case c = parsed(queryText("[count: candidates]"));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_TRUE(model.ok()) << model.statusText();
  EXPECT_EQ(model.counter_floors.at("candidates"), 3u) << "none committed: all three";
  // Planted: the interval shrinks to the first candidate returned; nothing
  // is committed either way, so only the count shows it.
  const Results d = planted("query-candidate-shrinks-interval", c, model);
  EXPECT_EQ(d.counters.at("candidates"), 1u);
  const Verdict v = compareResults(c, derivePlan(c), d, model);
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_NE(v.headline().find("R-RQ-CANDIDATES"), std::string::npos) << v.headline();
  EXPECT_NE(v.headline().find("device 1, at least 3"), std::string::npos) << v.headline();
}

TEST(CounterFloors, AConfirmingQueryOffersOnlyWhatLiesBeforeItsCommit) {
  // Near to far, the first is confirmed: the others lie beyond it (offered
  // in some orders only).
  const Case c = parsed(queryText("[count: candidates, confirm]"));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_TRUE(model.ok()) << model.statusText();
  EXPECT_EQ(model.counter_floors.at("candidates"), 1u);
}

TEST(CounterFloors, AQueryBlockThatMayEndTheLoopRaisesNoFloor) {
  const Case c = parsed(queryText("[count: candidates, terminate_query]"));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_TRUE(model.ok()) << model.statusText();
  EXPECT_FALSE(model.counter_floors.count("candidates"));
}

}  // namespace
}  // namespace rayspec
