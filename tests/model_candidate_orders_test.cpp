// Every candidate order in the model's exact tier (R-ORDER-UNSPEC, R-TIE):
// where the candidate programs may depend on the order candidates arrive in
// (model/order_dependence.h), or reports tie, every order of the candidates
// that matter runs in a what-if run, and each distinct outcome is legal
// (issue 55 items 1 and 2, issue 62 classes 2 and 5); past the bound a case
// whose sampled orders answer otherwise is a CaseError naming its block.
#include <gtest/gtest.h>

#include <array>
#include <set>
#include <string>

#include "compare/compare_results.h"
#include "model/candidate_orders.h"
#include "model_support.h"
#include "parse/parse_case.h"

namespace rayspec {
namespace candidate_orders_test {
namespace {

using namespace model_test;
using Key = std::array<uint32_t, 3>;

Results runExact(const Case& c) {
  return runTier(c, ModelTier::Exact, 1);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

// Three tilted non-opaque triangles (instances 0, 1, 2 at z 0, -1, -2, each
// leaning more than the one before, so that a BVH enters the far one's box
// first) under ray 0; ray 1 misses. BLOCK is the triangle block; `after`
// records the committed instance (value1) and type (value).
const char* kThreeTriangles = R"(rules: [R-ORDER-UNSPEC, R-RQ-COMMIT, R-RQ-TERMINATE]
scene:
  blas:
    flat:
      - triangles: {vertices: [[-5, -5, 0.2], [5, -5, -0.2], [0, 5, 0]]}
        flags: []
    leaning:
      - triangles: {vertices: [[-5, -5, 1.5], [5, -5, -1.5], [0, 5, 0]]}
        flags: []
    steep:
      - triangles: {vertices: [[-5, -5, 3.5], [5, -5, -3.5], [0, 5, 0]]}
        flags: []
  instances:
    - {blas: flat}
    - {blas: leaning, transform: {translate: [0, 0, -1]}}
    - {blas: steep, transform: {translate: [0, 0, -2]}}
rays:
  list:
    - {origin: [0.1, 0.2, 10], direction: [0, 0, -1]}
    - {origin: [30, 0.2, 10], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  raygen:
    - ray_query:
        triangle: BLOCK
        after:
          - record: {value: committed.type}
          - if: {ne: [committed.type, 0]}
            then: [record: {value1: committed.instance_id}]
outputs:
  per_ray: [value, value1]
)";

Case threeTriangles(const std::string& block) {
  return parseInline(replaced(kThreeTriangles, "BLOCK", block), "ray-query/orders");
}

// A device's results: the model's, with ray 0's value1 (the committed
// instance) set to `instance`.
Results deviceCommitting(const Results& model, uint32_t instance) {
  Results d = model;
  d.backend = "vulkan";
  d.ambiguous.clear();
  d.records[findRecordField("value1")->offset] = instance;
  return d;
}

// 55.1: a block that confirms only while nothing is committed commits
// whichever candidate comes first: every one of the three is legal. Before
// every order was tried, the ray was clear and a device committing the
// farthest failed on value1.
TEST(ModelCandidateOrders, ConfirmWhileNothingCommittedMakesEveryCandidateLegal) {
  const Case c = threeTriangles("[{if: {eq: [committed.type, 0]}, then: [confirm]}]");
  const Results r = runExact(c);
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(r.ambiguous[0].ray, 0u);
  EXPECT_EQ(r.ambiguous[0].reason, AmbiguityReason::Order);
  EXPECT_EQ(legal(r.ambiguous[0]), (std::set<Key>{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}));
  EXPECT_EQ(word(r, 0, "value1"), 0u);  // the model's own order: nearest first
  const Verdict far = compareResults(c, derivePlan(c), deviceCommitting(r, 2), r);
  EXPECT_EQ(far.status, Status::Pass) << far.headline();
}

// The same block confirming the closest only (reads committed.t) decides
// alike in every order: clear, and a device committing the farthest fails.
TEST(ModelCandidateOrders, ConfirmingTheClosestStaysClear) {
  const Case c = threeTriangles(
      "[{if: {or: [{eq: [committed.type, 0]}, {lt: [candidate.t, committed.t]}]}, then: "
      "[confirm]}]");
  const Results r = runExact(c);
  ASSERT_EQ(r.statusText(), "ok");
  EXPECT_TRUE(r.ambiguous.empty());
  const Verdict far = compareResults(c, derivePlan(c), deviceCommitting(r, 2), r);
  EXPECT_EQ(far.status, Status::Fail) << far.headline();
}

// 55.2: confirm on instances 0 and 2, terminate on 1. The order (2, 1, 0)
// commits 2 and ends; "each candidate first, the rest nearest first" never
// reached it.
TEST(ModelCandidateOrders, TerminateBetweenConfirmsReachesEveryOrder) {
  const Case c = threeTriangles(
      "[{if: {eq: [candidate.instance_id, 1]}, then: [terminate_query], else: [confirm]}]");
  const Results r = runExact(c);
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(r.ambiguous[0].reason, AmbiguityReason::Order);
  const std::set<Key> answers = legal(r.ambiguous[0]);
  EXPECT_TRUE(answers.count({2, 0, 0})) << "order (2, 1, 0)";
  EXPECT_TRUE(answers.count({0, 0, 0}));
  const Verdict far = compareResults(c, derivePlan(c), deviceCommitting(r, 2), r);
  EXPECT_EQ(far.status, Status::Pass) << far.headline();
}

// Item 3 of the vocabulary: a ray_query may say it is order-dependent; the
// model then tries every order there whatever its blocks read. A block that
// keeps the last candidate's instance in a local it never reads is found
// anyway (a write whose value an order decides).
TEST(ModelCandidateOrders, DeclaredOrLastWriterQueriesTryEveryOrder) {
  std::string text = replaced(kThreeTriangles, "BLOCK", "[confirm]");
  text = replaced(text, "    - ray_query:\n", "    - ray_query:\n        order_dependent: true\n");
  const Results declared = runExact(parseInline(text, "ray-query/declared"));
  ASSERT_EQ(declared.statusText(), "ok");
  EXPECT_TRUE(declared.ambiguous.empty()) << "confirm-all decides alike in every order";
  std::string last = replaced(kThreeTriangles, "BLOCK", "[set: {last: candidate.instance_id}]");
  last = replaced(last, "  raygen:\n", "  raygen:\n    - let: {last: 7}\n");
  last = replaced(last, "          - record: {value: committed.type}",
                  "          - record: {value: committed.type, value2: var.last}");
  last = replaced(last, "per_ray: [value, value1]", "per_ray: [value, value1, value2]");
  const Results r = runExact(parseInline(last, "ray-query/last-writer"));
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(r.ambiguous[0].reason, AmbiguityReason::Order);
  EXPECT_EQ(firstErrorAfter(kThreeTriangles, "    - ray_query:\n",
                            "    - ray_query:\n        order_dependent: maybe\n"),
            "pipeline.raygen[0].ray_query.order_dependent: expected true or false, not 'maybe'");
}

// Two stacked non-opaque triangles under ray 0 whose any-hit is ANY_HIT;
// the miss records the payload's value.
const char* kStacked = R"(rules: [R-ORDER-UNSPEC]
scene:
  blas:
    layers:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0], [-1, -1, -1], [2, -1, -1], [-1, 2, -1]]
        flags: [no_duplicate_any_hit]
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
    - [record: {hit: 0, value: payload.value}]
  hit_groups:
    - any_hit: ANY_HIT
      closest_hit: [record: {hit: 1}]
outputs:
  per_ray: [hit, value]
)";

// 62.2: an any-hit whose payload write depends on the order (the last
// candidate's primitive stays) makes the ray ambiguous, never clear; one
// that accumulates (a sum, alike in every order) stays clear.
TEST(ModelCandidateOrders, OrderDependentAnyHitPayloadIsNeverClear) {
  const Results last = runExact(parseInline(
      replaced(kStacked, "ANY_HIT", "[payload: {value: {add: [primitive_id, 1]}}, ignore]")));
  ASSERT_EQ(last.statusText(), "ok");
  ASSERT_EQ(last.ambiguous.size(), 1u);
  EXPECT_EQ(last.ambiguous[0].ray, 0u);
  EXPECT_EQ(last.ambiguous[0].reason, AmbiguityReason::Order);
  const Results sum = runExact(parseInline(
      replaced(kStacked, "ANY_HIT",
               "[payload: {value: {add: [payload.value, {add: [primitive_id, 1]}]}}, ignore]")));
  ASSERT_EQ(sum.statusText(), "ok");
  EXPECT_TRUE(sum.ambiguous.empty());
  EXPECT_EQ(word(sum, 0, "value"), 3u);
}

// Two unit boxes under ray 0 (instance 0 at z 0, instance 1 at z -3);
// INTERSECTION is their intersection program; closest-hit records the hit.
const char* kTwoBoxes = R"(rules: [R-TIE, R-ORDER-UNSPEC]
scene:
  blas:
    box:
      - aabbs: [[-1, -1, -0.5, 1, 1, 0.5]]
  instances:
    - {blas: box}
    - {blas: box, transform: {translate: [0, 0, -3]}}
rays:
  list:
    - {origin: [0, 0, 10], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss:
    - [record: {hit: 0}]
  hit_groups:
    - intersection: INTERSECTION
      closest_hit: [record: [hit, instance_id, primitive_id, hit_kind]]
outputs:
  per_ray: [hit, instance_id, primitive_id, hit_kind]
)";

Results twoBoxes(const std::string& intersection) {
  return runExact(parseInline(replaced(kTwoBoxes, "INTERSECTION", intersection), "ties/boxes"));
}

// 62.5 a: both boxes report at gl_RayTminEXT. The model's order commits the
// near box at tmin and never runs the far one (entered beyond tmin); a
// device meeting the far box first commits it there and the near box's
// report ties it: either is legal.
TEST(ModelCandidateOrders, TwoBoxesReportingAtTminTie) {
  const Results r = twoBoxes("[report: {t: ray_tmin, kind: 1}]");
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(legal(r.ambiguous[0]), (std::set<Key>{{0, 0, 0}, {1, 0, 0}}));
}

// 62.5 b: the near box reports at gl_RayTmaxEXT, the far one at its own top
// face (t 12.5). In the model's order the far box's report replaces the
// near one's; a device that commits the far box first sees tmax become 12.5
// and the near box's report lands on it (R-TIE: keep or replace).
TEST(ModelCandidateOrders, AReportAtTmaxLandsOnAnotherBoxsCommittedT) {
  const Results r = twoBoxes(
      "[{if: {eq: [instance_id, 0]}, then: [report: {t: ray_tmax, kind: 1}], else: [report: {t: "
      "{sub: [{z: object_ray_origin}, {z: aabb_max}]}, kind: 2}]}]");
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(legal(r.ambiguous[0]), (std::set<Key>{{0, 0, 0}, {1, 0, 0}}));
}

// 62.5 b (equal entry): two instances of one box at the same place are
// entered at the same t, which far-to-near does not reorder: each reporting
// at ray_tmax, whichever runs first commits at tmax and the other ties it.
TEST(ModelCandidateOrders, BoxesEnteredAtOneTTieWhicheverRunsFirst) {
  std::string text = replaced(kTwoBoxes, "translate: [0, 0, -3]", "translate: [0, 0, 0]");
  const Results r = runExact(
      parseInline(replaced(text, "INTERSECTION", "[report: {t: ray_tmax, kind: 1}]"), "ties/eq"));
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(legal(r.ambiguous[0]), (std::set<Key>{{0, 0, 0}, {1, 0, 0}}));
}

// 62.5 c: a box's second report lands on its own first report's committed t
// (its top face, kind 1, then again kind 2): keeping and replacing are both
// legal, so the ray is not clear (its hit_kind may be either).
TEST(ModelCandidateOrders, ASecondReportAtItsOwnCommittedTTies) {
  const std::string top = "{sub: [{z: object_ray_origin}, {z: aabb_max}]}";
  const Results r = twoBoxes("[{if: {eq: [instance_id, 0]}, then: [report: {t: " + top +
                             ", kind: 1}, report: {t: " + top + ", kind: 2}]}]");
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(r.ambiguous[0].reason, AmbiguityReason::TTie);
  EXPECT_EQ(word(r, 0, "hit_kind"), 2u);  // the model replaces
}

// Past kMaxOrderedCandidates the model samples orders: a block whose sample
// answers differently is a CaseError "order-dependent" naming the block's
// place, never judged.
TEST(ModelCandidateOrders, PastTheBoundADependentBlockIsACaseError) {
  std::string text = kThreeTriangles;
  std::string more;
  for (int k = 3; k < 3 + static_cast<int>(kMaxOrderedCandidates); ++k)
    more += "    - {blas: flat, transform: {translate: [0, 0, " + std::to_string(-k) + "]}}\n";
  text = replaced(text, "rays:\n", more + "rays:\n");
  const Case c =
      parseInline(replaced(text, "BLOCK", "[{if: {eq: [committed.type, 0]}, then: [confirm]}]"),
                  "ray-query/too-many");
  const Results r = runExact(c);
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.order_dependent.size(), 1u);
  EXPECT_NE(r.order_dependent[0].find("ray_query at ray-query/too-many.yaml:"), std::string::npos)
      << r.order_dependent[0];
  EXPECT_NE(r.order_dependent[0].find("reads committed.type"), std::string::npos);
  Results device = r;
  device.backend = "vulkan";
  const Verdict v = compareResults(c, derivePlan(c), device, r);
  EXPECT_EQ(v.status, Status::CaseError) << v.headline();
  EXPECT_NE(v.headline().find("order-dependent"), std::string::npos) << v.headline();
}

// The orders themselves: all permutations of the candidates that matter,
// the others in place; the sample past the bound.
TEST(ModelCandidateOrders, EveryOrderPermutesOnlyWhatMatters) {
  const auto orders = everyOrder(4, {0, 2, 3});
  ASSERT_EQ(orders.size(), 6u);
  EXPECT_EQ(orders[0], (std::vector<uint32_t>{0, 1, 2, 3}));
  for (const auto& o : orders) EXPECT_EQ(o[1], 1u);
  EXPECT_EQ(std::set<std::vector<uint32_t>>(orders.begin(), orders.end()).size(), 6u);
  std::vector<uint32_t> many(10);
  for (uint32_t k = 0; k < 10; ++k) many[k] = k;
  const auto sample = sampleOrders(10, many);
  EXPECT_EQ(sample.size(), 1 + 9 + 1 + 9 + kSampledOrders);
  EXPECT_EQ(sample[1][0], 1u);   // candidate 1 first
  EXPECT_EQ(sample[10][0], 9u);  // the reverse
}

}  // namespace
}  // namespace candidate_orders_test
}  // namespace rayspec
