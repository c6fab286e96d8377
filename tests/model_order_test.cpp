// Traversal order in the model's exact tier (R-ORDER-UNSPEC, R-TERMINATE):
// where an any-hit may terminate, the candidate a device meets first may end
// the traversal, so every such answer is legal (reason Order).
#include <gtest/gtest.h>

#include <array>
#include <set>
#include <string>
#include <utility>

#include "compare/compare_results.h"
#include "model/candidate_orders.h"
#include "model_support.h"
#include "parse/parse_case.h"

namespace rayspec {
namespace {

using namespace model_test;

// Two stacked non-opaque triangles (primitive 0 at z = 0, 1 at z = -1) under
// ray 0; ray 1 misses them. ANY_HIT is replaced by each test's any-hit.
const char* kStacked = R"(rules: [R-ORDER-UNSPEC, R-TERMINATE]
scene:
  blas:
    layers:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0], [-1, -1, -1], [2, -1, -1], [-1, 2, -1]]
        flags: []
  instances:
    - {blas: layers}
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
    - {origin: [5, 5, 1], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss:
    - [count: miss, record: {hit: 0}]
  hit_groups:
    - any_hit: ANY_HIT
      closest_hit: [count: closesthit, record: [hit, instance_id, geometry_index, primitive_id]]
outputs:
  counters: [miss, closesthit, anyhit]
  per_ray: [hit, instance_id, geometry_index, primitive_id]
)";

Case stacked(const std::string& any_hit) {
  std::string text = kStacked;
  text.replace(text.find("ANY_HIT"), 7, any_hit);
  return parseInline(text, "anyhit/order");
}

Results runExact(const Case& c) {
  return runTier(c, ModelTier::Exact, 1);
}

using Key = std::array<uint32_t, 3>;

TEST(ModelOrder, TerminatingAnyHitMakesEitherStackedTriangleLegal) {
  const Results r = runExact(stacked("[count: anyhit, terminate]"));
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(r.ambiguous[0].ray, 0u);
  EXPECT_EQ(r.ambiguous[0].reason, AmbiguityReason::Order);
  EXPECT_STREQ(ruleForAmbiguity(r.ambiguous[0].reason), "R-ORDER-UNSPEC");
  EXPECT_FALSE(r.ambiguous[0].from_query);  // a trace's
  EXPECT_EQ(legal(r.ambiguous[0]), (std::set<Key>{{0, 0, 0}, {0, 0, 1}}));
  // The model's own order: nearest first; its what-if runs leave no trace.
  EXPECT_EQ(answer(r, 0), (Key{0, 0, 0}));
  EXPECT_EQ(r.counters.at("anyhit"), 1u);
  EXPECT_EQ(r.counters.at("closesthit"), 1u);
  EXPECT_TRUE(r.undefined.empty());
}

// Judged as a device's (the model's results edited): the far triangle passes
// where a terminating any-hit makes it legal, and fails where whatever the
// order the traversal ends on the near one.
TEST(ModelOrder, AFarAnswerPassesOnlyWhereTheOrderAllowsIt) {
  auto far_device = [](const Results& model) {
    Results d = model;
    d.backend = "vulkan";
    d.ambiguous.clear();
    d.records[findRecordField("primitive_id")->offset] = 1;
    return d;
  };
  const Case any = stacked("[count: anyhit, terminate]");
  const Results any_model = runExact(any);
  const Verdict pass = compareResults(any, derivePlan(any), far_device(any_model), any_model);
  EXPECT_EQ(pass.status, Status::Pass) << pass.headline();
  const Case near = stacked("[count: anyhit, {if: {eq: [primitive_id, 0]}, then: [terminate]}]");
  const Results near_model = runExact(near);
  const Verdict fail = compareResults(near, derivePlan(near), far_device(near_model), near_model);
  EXPECT_EQ(fail.status, Status::Fail) << fail.headline();
}

// Terminating only on the far triangle: the model's order accepts the near
// one and never reaches the far one; a device meeting the far one first ends
// there. Both are legal.
TEST(ModelOrder, TerminateOnTheFarTriangleOnlyIsStillOrderDependent) {
  const Results r =
      runExact(stacked("[count: anyhit, {if: {eq: [primitive_id, 1]}, then: [terminate]}]"));
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(r.ambiguous[0].reason, AmbiguityReason::Order);
  EXPECT_EQ(legal(r.ambiguous[0]), (std::set<Key>{{0, 0, 0}, {0, 0, 1}}));
  EXPECT_EQ(answer(r, 0), (Key{0, 0, 0}));
}

// Answers that do not depend on the order stay clear: terminating on the
// near triangle (whatever comes first, it ends on it), an any-hit that never
// terminates, and opaque geometry (no any-hit runs).
TEST(ModelOrder, OrderIndependentAnswersStayClear) {
  for (const char* any_hit :
       {"[count: anyhit, {if: {eq: [primitive_id, 0]}, then: [terminate]}]", "[count: anyhit]",
        "[count: anyhit, {if: {eq: [primitive_id, 1]}, then: [ignore]}]"}) {
    const Results r = runExact(stacked(any_hit));
    ASSERT_EQ(r.statusText(), "ok");
    EXPECT_TRUE(r.ambiguous.empty())
        << any_hit << ": " << ambiguityReasonName(r.ambiguous[0].reason);
    EXPECT_EQ(answer(r, 0), (Key{0, 0, 0})) << any_hit;
  }
  Case opaque = stacked("[count: anyhit, terminate]");
  opaque.scene.blases[0].geometries[0].flags = kGeometryOpaque;
  const Results r = runExact(opaque);
  EXPECT_TRUE(r.ambiguous.empty());
  EXPECT_EQ(r.counters.at("anyhit"), 0u);
}

// Fuzz seed 150215 on Mesa 26.2.6, reduced: ray 0 crosses the lone edge
// x = 0 of triangle A (primitive 0, z = 0; the model hits it), so a device
// may hit or miss A; behind it the opaque B (primitive 1, z = -1) and the
// non-opaque C (geometry 1, z = -2) whose any-hit counts in payload word 0
// and ignores. With no ordering guarantee a device may run C's any-hit
// before it commits A or B: the legal records are (A, 0), (A, 1), (B, 0) and
// (B, 1), the last only where A's miss and C's place in the order combine.
const char* kLoneEdgeOverIgnored = R"(rules: [R-ORDER-UNSPEC, R-WATERTIGHT]
scene:
  blas:
    layers:
      - triangles:
          vertices: [[0, -1, 0], [2, -1, 0], [0, 2, 0], [-1, -1, -1], [2, -1, -1], [-1, 2, -1]]
        flags: [opaque]
      - triangles:
          vertices: [[-1, -1, -2], [2, -1, -2], [-1, 2, -2]]
        flags: [no_duplicate_any_hit]
  instances:
    - {blas: layers}
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  payloads: [{words: 1}]
  raygen:
    - trace: {payload: {word0: 0}}
    - record: {value: payload.word0}
  miss:
    - [record: {hit: 0}]
  hit_groups:
    - closest_hit: [record: [hit, geometry_index, primitive_id]]
    - any_hit: [payload: {word0: {add: [payload.word0, 1]}}, ignore]
      closest_hit: [record: [hit, geometry_index, primitive_id]]
outputs:
  per_ray: [hit, geometry_index, primitive_id, value]
)";

// The model's results as a device's, ray 0's record set to a hit on
// (geometry, primitive) with payload word 0 `value`.
Results deviceLeaving(const Results& model, uint32_t geometry, uint32_t primitive, uint32_t value) {
  Results d = model;
  d.backend = "vulkan";
  d.ambiguous.clear();
  d.records[findRecordField("geometry_index")->offset] = geometry;
  d.records[findRecordField("primitive_id")->offset] = primitive;
  d.records[findRecordField("value")->offset] = value;
  return d;
}

// Each legal record passes, A's miss combined with C's any-hit first too;
// a record no combination leaves (C's any-hit run twice, or C committed
// though its any-hit ignores it) fails.
TEST(ModelOrder, AnEdgeMissCombinesWithAFartherAnyHitFirst) {
  const Case c = parseInline(kLoneEdgeOverIgnored, "anyhit/lone-edge-order");
  const Plan plan = derivePlan(c);
  const Results model = runExact(c);
  ASSERT_EQ(model.statusText(), "ok");
  ASSERT_TRUE(model.order_dependent.empty()) << model.order_dependent[0];
  ASSERT_EQ(model.ambiguous.size(), 1u);
  EXPECT_EQ(model.ambiguous[0].reason, AmbiguityReason::Edge);
  EXPECT_EQ(legal(model.ambiguous[0]), (std::set<Key>{{0, 0, 0}, {0, 0, 1}}));
  // The model's own answer: A first, C's any-hit never runs.
  EXPECT_EQ(answer(model, 0), (Key{0, 0, 0}));
  EXPECT_EQ(word(model, 0, "value"), 0u);
  for (const auto& [primitive, value] :
       std::set<std::pair<uint32_t, uint32_t>>{{0, 0}, {0, 1}, {1, 0}, {1, 1}}) {
    const Verdict v = compareResults(c, plan, deviceLeaving(model, 0, primitive, value), model);
    EXPECT_EQ(v.status, Status::Pass)
        << "primitive " << primitive << ", value " << value << ": " << v.headline();
  }
  for (const Key& k : std::set<Key>{{0, 1, 2}, {0, 0, 2}, {1, 0, 1}}) {
    const Verdict v = compareResults(c, plan, deviceLeaving(model, k[0], k[1], k[2]), model);
    EXPECT_EQ(v.status, Status::Fail) << k[0] << " " << k[1] << " " << k[2];
  }
}

// Past kMaxCombinedOrderRuns: three pairs of coinciding lone-edge triangles
// (z 0, -0.25, -0.5; the model's ray misses them all), non-opaque, their
// any-hit counting in payload word 0 and ignoring. Each pair may leave
// none, one or the other hit (26 legal decisions beside the model's own),
// each of the 720 orders of the six under 4 tie rules: 74880 what-if runs.
// The model tries none of the combinations and says so: the case is a
// CaseError naming the bound, neither a Pass nor a Fail of any device.
const char* kThreeLoneEdgePairs = R"(rules: [R-ORDER-UNSPEC, R-WATERTIGHT]
scene:
  blas:
    pairs:
      - triangles:
          vertices: [[0, -1, 0], [0, 2, 0], [-2, -1, 0], [0, -1, 0], [0, 2, 0], [-2, -1, 0],
                     [0, -1, -0.25], [0, 2, -0.25], [-2, -1, -0.25],
                     [0, -1, -0.25], [0, 2, -0.25], [-2, -1, -0.25],
                     [0, -1, -0.5], [0, 2, -0.5], [-2, -1, -0.5], [0, -1, -0.5], [0, 2, -0.5], [-2, -1, -0.5]]
        flags: [no_duplicate_any_hit]
  instances:
    - {blas: pairs}
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
pipeline:
  payloads: [{words: 1}]
  raygen:
    - trace: {payload: {word0: 0}}
    - record: {value: payload.word0}
  miss:
    - [record: {hit: 0}]
  hit_groups:
    - any_hit: [payload: {word0: {add: [payload.word0, 1]}}, ignore]
      closest_hit: [record: [hit, geometry_index, primitive_id]]
outputs:
  per_ray: [hit, geometry_index, primitive_id, value]
)";

TEST(ModelOrder, CombinationsPastTheBoundAreACaseError) {
  const Case c = parseInline(kThreeLoneEdgePairs, "anyhit/lone-edge-pairs-order");
  const Results model = runExact(c);
  ASSERT_EQ(model.statusText(), "ok");
  ASSERT_EQ(model.order_dependent.size(), 1u);
  const std::string& what = model.order_dependent[0];
  EXPECT_NE(what.find("26 legal decisions of its unsure candidates"), std::string::npos) << what;
  EXPECT_NE(
      what.find("make 74880 what-if runs, more than the " + std::to_string(kMaxCombinedOrderRuns)),
      std::string::npos)
      << what;
  Results device = model;
  device.backend = "vulkan";
  device.ambiguous.clear();
  EXPECT_EQ(compareResults(c, derivePlan(c), device, model).status, Status::CaseError);
}

}  // namespace
}  // namespace rayspec
