// A correct driver never fails: a ray through a shared edge answered by each
// of its legal answers, the shaders run as that answer makes them run
// (ModelFaults::legal_answer), Passes; a device passing between the edge's
// triangles (ModelFaults::pass_between_edges) gets a QualityWarning naming
// the ray (compare_records.cpp, ambiguous_shared.cpp); and the legal devices
// of `rayspec mutate` (mutate/legal_devices.h) find no false alarm there.
#include <gtest/gtest.h>

#include <bit>
#include <string_view>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "model_support.h"
#include "mutate/legal_devices.h"

namespace rayspec {
namespace {

using model_test::ambiguityOf;
using model_test::diagonalSquareBlas;
using model_test::kTriangleHitAndMiss;
using model_test::parseInline;

// Two non-opaque triangles share the diagonal x = y of a square at z = 0; a
// floor lies behind at z = -2. Ray 0 meets the diagonal exactly; ray 1 hits
// the square clearly. `any_hit` is the hit group's any-hit program.
std::string edgeCase(const std::string& any_hit) {
  return R"(rules: [R-WATERTIGHT]
description: an edge ray with a floor behind
scene:
  blas:
)" + diagonalSquareBlas("[]") +
         R"(    floor:
      - triangles:
          vertices: [[-9, -9, -2], [9, -9, -2], [0, 9, -2]]
        flags: []
  instances: [{blas: square}, {blas: floor}]
rays:
  list:
    - {origin: [0.25, 0.25, 5], direction: [0, 0, -1]}
    - {origin: [0.5, -0.5, 5], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss:
    - [count: miss, record: {hit: 0}]
  hit_groups:
    - any_hit: )" +
         any_hit + R"(
      closest_hit:
        - count: chit
        - record: [hit, instance_id, primitive_id, hit_t, barycentrics]
outputs:
  counters: [miss, chit]
  per_ray: [hit, instance_id, primitive_id, hit_t, barycentrics]
)";
}

Results runAs(const Case& c, uint32_t legal_answer, bool pass_between) {
  ModelOptions o{ModelTier::Exact, 1};
  o.faults.legal_answer = legal_answer;
  o.faults.pass_between_edges = pass_between;
  Results r = perfectDevice(c, runOnModel(c, derivePlan(c), o));
  r.backend = "vulkan";
  return r;
}

TEST(LegalAnswers, EveryLegalAnswerOfAnEdgeRayPassesWithItsOwnT) {
  // The odd triangle is ignored: the ray may take the even one (t 5) or, by
  // the odd one, the floor behind (t 7). Each is a legal, watertight answer.
  const Case c = parseInline(edgeCase("[{if: {odd: primitive_id}, then: [ignore]}]"));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{ModelTier::Exact, 1});
  const RayAmbiguity* a = ambiguityOf(model, 0);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->reason, AmbiguityReason::Edge);
  std::set<uint32_t> instances;
  for (const Candidate& k : a->candidates)
    if (k.hit) instances.insert(k.instance);
  ASSERT_EQ(instances, (std::set<uint32_t>{0, 1})) << "the square and the floor are legal";
  std::set<uint32_t> taken;
  for (uint32_t j = 0; j < a->candidates.size(); ++j) {
    const Results device = runAs(c, j, false);
    const uint32_t* rec = &device.records[0];
    taken.insert(rec[findRecordField("instance_id")->offset]);
    const Verdict v = compareResults(c, derivePlan(c), device, model);
    EXPECT_EQ(v.status, Status::Pass) << "answer " << j << ": " << v.headline();
  }
  EXPECT_EQ(taken, (std::set<uint32_t>{0, 1})) << "each legal answer was taken by a device";
}

TEST(LegalAnswers, AWrongTOnALegalAnswerStillFails) {
  const Case c = parseInline(edgeCase("[{if: {odd: primitive_id}, then: [ignore]}]"));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{ModelTier::Exact, 1});
  Results device = runAs(c, 1, false);
  float* t = reinterpret_cast<float*>(&device.records[findRecordField("hit_t")->offset]);
  *t += 0.5f;  // between the square's 5 and the floor's 7: no legal hit's t
  const Verdict v = compareResults(c, derivePlan(c), device, model);
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
}

TEST(LegalAnswers, PassingBetweenTheTrianglesOfASharedEdgeIsAQualityWarning) {
  // Neither triangle is ignored: a watertight device hits one of them, and
  // the floor is reached only between them.
  const Case c = parseInline(edgeCase("[{if: {eq: [primitive_id, 7]}, then: [ignore]}]"));
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{ModelTier::Exact, 1});
  const RayAmbiguity* a = ambiguityOf(model, 0);
  ASSERT_NE(a, nullptr);
  ASSERT_EQ(a->leak_answers.size(), 1u);
  EXPECT_EQ(a->leak_answers[0].instance, 1u);
  EXPECT_NEAR(a->leak_answers[0].t, 7.0, 1e-5);
  const Results device = runAs(c, 0, true);
  EXPECT_EQ(device.records[findRecordField("instance_id")->offset], 1u);
  const Verdict v = compareResults(c, derivePlan(c), device, model);
  EXPECT_EQ(v.status, Status::QualityWarning) << v.headline();
  bool named = false;
  for (const Finding& f : v.findings)
    named = named || (f.rule == "R-WATERTIGHT" && f.status == Status::QualityWarning &&
                      f.rays == std::vector<uint32_t>{0});
  EXPECT_TRUE(named) << v.headline();
}

// With nothing behind the edge, passing between its triangles is a miss: the
// miss and closest-hit counters move with it, as far as the device's own
// records show leaks (a QualityWarning), and no further (a Fail).
TEST(LegalAnswers, CountersMoveWithALeakOnlyAsFarAsTheRecordsShowIt) {
  std::string text = edgeCase("[{if: {eq: [primitive_id, 7]}, then: [ignore]}]");
  const std::string floor = "[[-9, -9, -2], [9, -9, -2], [0, 9, -2]]";
  text.replace(text.find(floor), floor.size(), "[[50, 50, -2], [60, 50, -2], [50, 60, -2]]");
  const Case c = parseInline(text);
  const Results model = runOnModel(c, derivePlan(c), ModelOptions{ModelTier::Exact, 1});
  const Results leaky = runAs(c, 0, true);
  EXPECT_EQ(leaky.counters.at("miss"), model.counters.at("miss") + 1);
  const Verdict v = compareResults(c, derivePlan(c), leaky, model);
  EXPECT_EQ(v.status, Status::QualityWarning) << v.headline();
  Results counted = perfectDevice(c, model);  // the same counters, no leak in its records
  counted.backend = "vulkan";
  counted.counters = leaky.counters;
  EXPECT_EQ(compareResults(c, derivePlan(c), counted, model).status, Status::Fail);
}

TEST(LegalDevices, EachLegalVariantOfTheEdgeCasePasses) {
  for (const char* any_hit : {"[{if: {odd: primitive_id}, then: [ignore]}]",
                              "[{if: {eq: [primitive_id, 7]}, then: [ignore]}]"}) {
    const Case c = parseInline(edgeCase(any_hit));
    const Plan plan = derivePlan(c);
    const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
    std::map<std::string, LegalDevice> by_name;
    for (const LegalDevice& d : judgeLegalDevices(c, plan, model, 1)) by_name[d.name] = d;
    for (const auto& [name, d] : by_name)
      EXPECT_FALSE(d.false_alarm) << any_hit << " " << name << ": " << d.headline;
    ASSERT_TRUE(by_name.count("answer-1"));
    EXPECT_TRUE(by_name["answer-1"].applied) << by_name["answer-1"].what;
    ASSERT_TRUE(by_name.count("tolerance-bound"));
    EXPECT_TRUE(by_name["tolerance-bound"].applied);
    EXPECT_EQ(by_name["tolerance-bound"].status, Status::Pass);
    ASSERT_TRUE(by_name.count("any-hit-runs-twice"));
    EXPECT_TRUE(by_name["any-hit-runs-twice"].applied) << by_name["any-hit-runs-twice"].what;
  }
}

// The judge as it was before this check knew each legal hit's t (issue 43:
// every answer of an edge ray was taken to have the model's t): the legal
// devices must catch it. Here the candidates' t are dropped to NaN and the
// model's own t put in their place, as the old check assumed; without the
// replays (RayAmbiguity::replays: a ray past their bound, an older bundle),
// whose records would give each answer's own t, the judge relies on them.
TEST(LegalDevices, AJudgeThatAssumesOneTPerEdgeRayIsCaught) {
  const Case c = parseInline(edgeCase("[{if: {odd: primitive_id}, then: [ignore]}]"));
  const Plan plan = derivePlan(c);
  Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
  const float own_t =
      reinterpret_cast<const float&>(model.records[findRecordField("hit_t")->offset]);
  for (RayAmbiguity& a : model.ambiguous) {
    a.replays.clear();
    for (Candidate& k : a.candidates) k.t = own_t;
  }
  bool caught = false;
  for (const LegalDevice& d : judgeLegalDevices(c, plan, model, 1))
    caught = caught || (d.false_alarm && d.rule == "R-PREC" && d.ray == 0);
  EXPECT_TRUE(caught) << "a judge holding every legal hit to the model's t fails a legal device";
}

// R-AABB-CONS: two boxes side by side, a ray down the middle of the first.
// An intersection program that reports without testing its box answers
// otherwise on a device that runs it for the neighbour too (aabb-neighbours:
// a false alarm the case, not the device, is to blame); one that reports
// only where the ray crosses its box answers the same.
std::string neighbourBoxes(const std::string& intersection) {
  return R"(rules: [R-AABB-CONS]
description: two boxes side by side
scene:
  blas:
    boxes:
      - aabbs: [[-2, -1, -1, 0, 1, 1], [0.5, -1, -1, 2.5, 1, 1]]
  instances: [{blas: boxes}]
rays:
  list:
    - {origin: [-1, 0, 5], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss:
    - [record: {hit: 0}]
  hit_groups:
    - intersection: )" +
         intersection + R"(
      closest_hit:
        - record: [hit, primitive_id]
outputs:
  per_ray: [hit, primitive_id]
)";
}

TEST(LegalDevices, AnIntersectionProgramRunForANeighbourBoxIsHeldToTheCase) {
  const std::string unconditional = "[report: {t: {sub: [4.0, {float: primitive_id}]}, kind: 0}]";
  const std::string tested =
      "[{if: {and: [{le: [{x: aabb_min}, {x: object_ray_origin}]}, {le: [{x: object_ray_origin}, "
      "{x: aabb_max}]}]}, then: " +
      unconditional + "}]";
  for (const auto& [program, alarm] : {std::pair{unconditional, true}, std::pair{tested, false}}) {
    const Case c = parseInline(neighbourBoxes(program));
    const Plan plan = derivePlan(c);
    const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
    bool found = false;
    for (const LegalDevice& d : judgeLegalDevices(c, plan, model, 1)) {
      if (d.name != "aabb-neighbours") continue;
      found = true;
      EXPECT_TRUE(d.applied || !alarm) << d.what;
      EXPECT_EQ(d.false_alarm, alarm) << program << ": " << d.headline;
    }
    EXPECT_TRUE(found);
  }
}

// A ray in a triangle's plane (model/in_plane.h): the tilted triangle of
// plane y = z, ray 0 runs along x in it and across the triangle for t in
// [4.5, 5.5] (to rounding); ray 1 hits it from above. Both programs write a
// number and a colour the hit's t does not reach, and `hit_t` straight into
// its field: the ray keeps its replays (the model's miss, a hit at the
// span's middle), held as a whole, hit_t to the span.
std::string inPlaneCase(const std::string& value) {
  return R"(rules: [R-PREC]
description: a ray in a tilted triangle's plane
scene:
  blas:
    tri:
      - triangles: {vertices: [[-1, -1, -1], [1, -1, -1], [0, 1, 1]]}
  instances: [{blas: tri}]
rays:
  list:
    - {origin: [-5, 0, 0], direction: [1, 0, 0]}
    - {origin: [0, 0, 5], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss:
    - [record: {hit: 0, value: 3, color: [0.0, 0.0, 0.0, 1.0]}]
  hit_groups:
    - closest_hit:
        - record: {hit: 1, primitive_id: primitive_id, hit_t: hit_t, value: )" +
         value + R"(, color: [0.25, 0.5, 0.75, 1.0]}
outputs:
  per_ray: [hit, primitive_id, hit_t, value, color]
)";
}

TEST(LegalDevices, ARayInATrianglesPlaneKeepsItsReplaysWhereItsTReachesNoFreeField) {
  const Case c = parseInline(inPlaneCase("{add: [primitive_id, 7]}"));
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
  const RayAmbiguity* a = ambiguityOf(model, 0);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->reason, AmbiguityReason::InPlane);
  EXPECT_EQ(a->replays.size(), 2u) << "the miss and a hit across the triangle";
  std::map<std::string, LegalDevice> by_name;
  for (const LegalDevice& d : judgeLegalDevices(c, plan, model, 1)) by_name[d.name] = d;
  for (const auto& [name, d] : by_name) EXPECT_FALSE(d.false_alarm) << name << ": " << d.headline;
  ASSERT_TRUE(by_name.count("answer-1"));
  EXPECT_TRUE(by_name["answer-1"].applied) << by_name["answer-1"].what;
  ASSERT_TRUE(by_name.count("tolerance-bound"));
  EXPECT_TRUE(by_name["tolerance-bound"].applied) << by_name["tolerance-bound"].what;
  // The hit anywhere across the triangle (entry, middle, exit): Pass; the
  // hit's number or colour wrong, or the miss's number: Fail (before, with
  // no replays, only what the miss and the hit share was judged).
  const Results hit = runAs(c, 1, false);
  ASSERT_EQ(hit.records[findRecordField("hit")->offset], 1u);
  auto at = [](Results& r, const char* field) {
    return reinterpret_cast<float*>(&r.records[findRecordField(field)->offset]);
  };
  for (const float t : {4.5f, 5.0f, 5.5f}) {
    Results d = hit;
    *at(d, "hit_t") = t;
    EXPECT_EQ(compareResults(c, plan, d, model).status, Status::Pass) << t;
  }
  Results past = hit;
  *at(past, "hit_t") = 6.5f;  // x 1.5: beyond the triangle
  EXPECT_EQ(compareResults(c, plan, past, model).status, Status::Fail);
  for (const char* field : {"value", "color"}) {
    for (const Results* answer : {&hit, &model}) {
      Results d = *answer;
      d.backend = "vulkan";
      uint32_t& word = d.records[findRecordField(field)->offset];
      word = std::string_view(field) == "value" ? word + 1 : std::bit_cast<uint32_t>(0.125f);
      const Verdict v = compareResults(c, plan, d, model);
      EXPECT_EQ(v.status, Status::Fail) << field << ": " << v.headline();
    }
  }
}

// A number computed from the hit's t: each t across the triangle leaves
// another, so the ray keeps no replays (held to what its answers share).
TEST(LegalDevices, ARayInATrianglesPlaneKeepsNoReplaysWhereItsTReachesAFreeField) {
  const Case c = parseInline(inPlaneCase("{uint: {mul: [hit_t, 1000.0]}}"));
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
  const RayAmbiguity* a = ambiguityOf(model, 0);
  ASSERT_NE(a, nullptr);
  EXPECT_TRUE(a->replays.empty());
  for (const LegalDevice& d : judgeLegalDevices(c, plan, model, 1))
    EXPECT_FALSE(d.false_alarm) << d.name << ": " << d.headline;
}

// A ray nearly in the tilted triangle's plane: its line crosses the plane
// beside the triangle (t 8), under it by about 3e-6 where it runs across
// (t in [4.5, 5.5]), its determinant within its bound and the edge functions
// clearly of both signs (model/watertight.cpp, nearlyInPlane): no longer
// clearly outside, a hit anywhere across (either face) is legal, and so is
// the miss; a hit past the triangle still fails, and so does a miss of the
// clear ray 1.
TEST(LegalDevices, ARayNearlyInATrianglesPlaneMayHitItAnywhereAcross) {
  std::string text = inPlaneCase("{add: [primitive_id, 7]}");
  const std::string in_plane = "{origin: [-5, 0, 0], direction: [1, 0, 0]}";
  text.replace(
      text.find(in_plane), in_plane.size(),
      "{origin: [-5, -5.04765876030433e-06, 0], direction: [1, 6.309573450380412e-07, 0]}");
  const Case c = parseInline(text);
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
  const RayAmbiguity* a = ambiguityOf(model, 0);
  ASSERT_NE(a, nullptr) << "a clear miss before";
  EXPECT_EQ(a->reason, AmbiguityReason::InPlane);
  for (const LegalDevice& d : judgeLegalDevices(c, plan, model, 1))
    EXPECT_FALSE(d.false_alarm) << d.name << ": " << d.headline;
  const Results hit = runAs(c, 1, false);
  ASSERT_EQ(hit.records[findRecordField("hit")->offset], 1u);
  auto hit_t_of = [](Results& r) {
    return reinterpret_cast<float*>(&r.records[findRecordField("hit_t")->offset]);
  };
  for (const float t : {4.5f, 5.5f}) {
    Results d = hit;
    *hit_t_of(d) = t;
    EXPECT_EQ(compareResults(c, plan, d, model).status, Status::Pass) << t;
  }
  Results past = hit;
  *hit_t_of(past) = 8.0f;  // where the line crosses the plane, beside the triangle
  EXPECT_EQ(compareResults(c, plan, past, model).status, Status::Fail);
  Results missed = perfectDevice(c, model);
  missed.backend = "vulkan";
  std::copy(missed.records.begin(), missed.records.begin() + recordWords(),
            missed.records.begin() + recordWords());
  EXPECT_EQ(compareResults(c, plan, missed, model).status, Status::Fail);
}

// The counter floors (model/counter_floors.cpp) hold on every legal device:
// a box's leading report's any-hit before the committed hit, a ray query's
// blocks for the candidates before its commit. Non-opaque boxes (the near
// box's report ignored, the far one's committed), and three triangles
// under a ray query whose block counts (and confirms, or not).
const char* kReportedBoxes = R"(rules: [R-ISECT-REPORT]
description: reports before the committed hit
scene:
  blas:
    b: [{aabbs: [[-1, -1, -1, 1, 1, 1], [3, -1, -1, 5, 1, 1]], flags: []}]
  instances: [{blas: b}]
rays:
  list: [{origin: [-5, 0.125, 0.0625], direction: [1, 0, 0]}]
  tmin: 0.001
  tmax: 100
pipeline:
  miss: [[record: {hit: 0}]]
  hit_groups:
    - intersection: [count: isect, report: {t: {max: [sphere_near, ray_tmin]}, kind: 1}]
      any_hit: [count: ahit, {if: {eq: [primitive_id, 0]}, then: [ignore]}]
      closest_hit: [record: [hit, primitive_id]]
outputs:
  counters: [isect, ahit]
  per_ray: [hit, primitive_id]
)";

std::string queriedTriangles(const std::string& block) {
  return R"(rules: [R-RQ-CANDIDATES]
description: a query's candidates before its commit
scene:
  blas:
    tri: [{triangles: {vertices: [[-5, -5, 0], [5, -5, 0], [0, 5, 0]]}, flags: []}]
  instances:
    - {blas: tri}
    - {blas: tri, transform: {translate: [0, 0, -1]}}
    - {blas: tri, transform: {translate: [0, 0, -2]}}
rays:
  list: [{origin: [0.1, 0.2, 10], direction: [0, 0, -1]}]
  tmin: 0.001
  tmax: 100
pipeline:
  raygen:
    - ray_query:
        triangle: )" +
         block + R"(
        after: [record: {value: committed.type}]
outputs:
  counters: [candidates]
  per_ray: [value]
)";
}

TEST(LegalDevices, NoLegalDeviceFallsBelowTheCounterFloors) {
  size_t applied = 0;  // devices that differ from the model (a query confirming none: none)
  for (const std::string& text :
       {std::string(kReportedBoxes), queriedTriangles("[count: candidates]"),
        queriedTriangles("[count: candidates, {if: {eq: [candidate.instance_id, 1]}, then: "
                         "[confirm]}]")}) {
    const Case c = parseInline(text);
    const Plan plan = derivePlan(c);
    const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
    ASSERT_TRUE(model.ok()) << model.statusText();
    ASSERT_FALSE(model.counter_floors.empty()) << text;
    for (const LegalDevice& d : judgeLegalDevices(c, plan, model, 1)) {
      applied += d.applied;
      EXPECT_FALSE(d.false_alarm) << d.name << ": " << d.headline << "\n" << text;
    }
  }
  EXPECT_GE(applied, 4u) << "other orders (and runs) than the model's";
}

// A scene of one candidate key has one order: the legal devices that decide
// candidates in another order (reverse-order, permuted-order-N, last-*) are
// not made there (each would run the model again to answer as it did: 38 of
// the 48 s `rayspec mutate` took on a launch of 2^23 ids); a scene of
// several keys keeps them all.
TEST(LegalDevices, OnlyScenesOfSeveralCandidatesGetOtherOrders) {
  const Case one = parseInline(std::string("rules: [R-BUILTIN]\ndescription: one triangle\n") +
                               kTriangleHitAndMiss + R"(  tmin: 0.001
  tmax: 100
pipeline:
  miss:
    - [record: {hit: 0}]
  hit_groups:
    - any_hit: [count: ahit]
      closest_hit: [record: [hit, primitive_id]]
outputs:
  counters: [ahit]
  per_ray: [hit, primitive_id]
)");
  const Case several = parseInline(edgeCase("[{if: {odd: primitive_id}, then: [ignore]}]"));
  EXPECT_TRUE(oneCandidateAtMost(one.scene));
  EXPECT_FALSE(oneCandidateAtMost(several.scene));
  const char* const kOrders[] = {"reverse-order", "permuted-order-1", "permuted-order-2",
                                 "permuted-order-3"};
  for (const Case* c : {&one, &several}) {
    const Plan plan = derivePlan(*c);
    const Results model = runOnModel(*c, plan, ModelOptions{ModelTier::Exact, 1});
    ASSERT_TRUE(model.ok()) << model.statusText();
    std::map<std::string, LegalDevice> by_name;
    size_t last = 0;
    for (const LegalDevice& d : judgeLegalDevices(*c, plan, model, 1)) {
      by_name[d.name] = d;
      last += d.name.rfind("last-", 0) == 0;
      EXPECT_FALSE(d.false_alarm) << d.name << ": " << d.headline;
    }
    const bool single = c == &one;
    EXPECT_EQ(last, single ? 0u : 3u) << c->description;
    for (const char* order : kOrders) {
      ASSERT_TRUE(by_name.count(order)) << order;
      const bool made = by_name[order].what.find("nothing in the case") == std::string::npos;
      EXPECT_EQ(made, !single) << order << ": " << by_name[order].what;
    }
  }
}

}  // namespace
}  // namespace rayspec
