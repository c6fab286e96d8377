// Traversal order in the model's exact tier (R-ORDER-UNSPEC, R-TERMINATE):
// where an any-hit may terminate, the candidate a device meets first may end
// the traversal, so every such answer is legal (reason Order).
#include <gtest/gtest.h>

#include <array>
#include <set>
#include <string>

#include "compare/compare_results.h"
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

}  // namespace
}  // namespace rayspec
