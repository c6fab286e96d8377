// Queries stepped in turn (ray_queries) and a query initialized again in
// the middle of its traversal (restart_query), issue 55: what the model
// answers in every tier, the faults that break them, the case errors of
// stepped queries that share what they write and of endless restarts, and
// the parse and check errors, each naming its field.
#include <set>
#include <string>

#include "compare/compare_results.h"
#include "model_suite_runs.h"

namespace rayspec::model_test {
namespace stepped_queries {  // named: the unity build joins the other query tests

TEST(ModelSteppedQueries, EachQueryDecidesAndReadsItsOwnCandidates) {
  for (ModelTier tier : kTiers) {
    const Results r = runSuiteCase("ray-query/stepped-queries", tier);
    EXPECT_EQ(column(r, "value", 2), (V{1, 1})) << modelTierName(tier);  // query 0: instance 1
    EXPECT_EQ(column(r, "value1", 2), (V{3, 3}));  // query 0 saw instances 0 and 1
    EXPECT_EQ(column(r, "value2", 2), (V{7, 7}));  // query 1 (tmin 11.5): instance 2
    EXPECT_EQ(column(r, "value3", 2), (V{1, 1}));
    EXPECT_EQ(column(r, "value4", 2), (V{2, 1}));  // query 2: the box generated, or instance 2
    EXPECT_EQ(column(r, "value5", 2), (V{3, 2}));
    EXPECT_EQ(column(r, "value6", 2), (V{1, 0}));
    EXPECT_FLOAT_EQ(fword(r, 0, "color"), 11.0f);
    EXPECT_FLOAT_EQ(fword(r, 0, "color2", 1), 11.5f);  // query.ray_tmin of its own query
    EXPECT_FLOAT_EQ(fword(r, 0, "color3"), 9.5f);
    EXPECT_FLOAT_EQ(fword(r, 1, "color3"), 12.0f);
    EXPECT_TRUE(r.undefined.empty());
    EXPECT_TRUE(r.order_dependent.empty());
  }
}

TEST(ModelSteppedQueries, ARestartDiscardsWhatIsCommittedAndGoesOnWithTheNewRay) {
  for (ModelTier tier : kTiers) {
    const Results r = runSuiteCase("ray-query/restart-mid-traversal", tier);
    EXPECT_EQ(column(r, "value", 2), (V{9, 9})) << modelTierName(tier);  // instance 3
    EXPECT_EQ(column(r, "value1", 2), (V{1, 1}));
    EXPECT_EQ(column(r, "value2", 2), (V{8, 8}));  // of instances 0..3, the new ray's only
    EXPECT_EQ(column(r, "value3", 2), (V{1, 1}));
    EXPECT_FLOAT_EQ(fword(r, 0, "color"), 15.0f);
    EXPECT_FLOAT_EQ(fword(r, 0, "color", 1), 20.1f);  // the getters read the new ray
    // The model's own order (nearest first): query B restarts at instance
    // 0 and commits instance 1 beyond it.
    EXPECT_EQ(column(r, "value4", 2), (V{0, 0}));
    EXPECT_EQ(column(r, "value6", 2), (V{1, 1}));
    // Stepped: C0 keeps instance 0, C1 restarts along x = 20.1.
    EXPECT_EQ(column(r, "value8", 2), (V{0, 0}));
    EXPECT_EQ(column(r, "value9", 2), (V{9, 9}));
    EXPECT_FLOAT_EQ(fword(r, 1, "color2", 1), 20.1f);
    EXPECT_TRUE(r.endless_restarts.empty());
  }
}

// Which candidate restarts query B is the order's: every order is tried,
// and its three answers (restarted at instance 0, 1 or 2) are legal, each
// replayed through the ray as a whole.
TEST(ModelSteppedQueries, TheCandidateThatRestartsIsTheOrders) {
  const Results r = runSuiteCase("ray-query/restart-mid-traversal", ModelTier::Exact);
  ASSERT_EQ(r.ambiguous.size(), 2u);
  for (const RayAmbiguity& a : r.ambiguous) {
    EXPECT_EQ(a.reason, AmbiguityReason::Order);
    // (query A's bit mask may also hold instance 4: more replays than 3)
    ASSERT_GE(a.replays.size(), 3u);
    std::set<uint32_t> first;
    for (const LegalReplay& p : a.replays)
      first.insert(p.record[findRecordField("value4")->offset]);
    EXPECT_EQ(first, (std::set<uint32_t>{0, 1, 2}));
  }
}

TEST(ModelSteppedQueries, FaultKnobsChangeTheirCases) {
  ModelFaults f;
  auto differs = [&](const char* name) {
    const Results good = runSuiteCase(name, ModelTier::Exact);
    const Results bad = runSuiteCase(name, ModelTier::Exact, f);
    return good.records != bad.records;
  };
  f.rq_restart_keeps_committed = true;
  EXPECT_TRUE(differs("ray-query/restart-mid-traversal"));
  EXPECT_FALSE(differs("ray-query/stepped-queries"));  // no restart there
  f = {};
  f.rq_step_wrong_query = true;
  EXPECT_TRUE(differs("ray-query/stepped-queries"));
  EXPECT_TRUE(differs("ray-query/restart-mid-traversal"));
  EXPECT_FALSE(differs("ray-query/two-queries"));  // nested, not stepped
}

const char* kSteppedCase =
    "rules: [R-RQ-COMMIT]\n"
    "scene:\n"
    "  blas: {t: [{triangles: {vertices: [[-5, -5, 0], [5, -5, 0], [0, 5, 0]]}, flags: []}]}\n"
    "  instances: [{blas: t}, {blas: t, transform: {translate: [0, 0, -1]}}]\n"
    "rays: {list: [{origin: [0.1, 0.2, 1], direction: [0, 0, -1]}], tmax: 10}\n"
    "pipeline:\n"
    "  raygen:\n"
    "    - let: {a: 0, b: 0}\n"
    "    - ray_queries:\n"
    "        - triangle: [{set: {a: {add: [var.a, 1]}}}, confirm]\n"
    "          after: [record: {value: var.a}]\n"
    "        - triangle: [{set: {b: {add: [var.b, 1]}}}]\n"
    "          after: [record: {value1: var.b}]\n"
    "outputs: {per_ray: [value, value1]}\n";

std::string edited(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

TEST(ModelSteppedQueries, ParseAndCheckErrorsNameTheField) {
  const std::string text = kSteppedCase;
  EXPECT_EQ(firstErrorAfter(text, "confirm]\n", "confirm]\n"), "(no error)");
  EXPECT_EQ(firstErrorAfter(text, "[{set: {b: {add: [var.b, 1]}}}]", "[break]"),
            "pipeline.raygen[1].ray_queries[1].triangle[0]: 'break' in a candidate block of a "
            "ray_queries query: the queries are stepped in turn in one loop, which a break "
            "would leave for all of them (use terminate_query to end this one)");
  EXPECT_EQ(firstErrorAfter(text, "[{set: {b: {add: [var.b, 1]}}}]", "[terminate_query]"),
            "(no error)");
  const std::string one = edited(text,
                                 "        - triangle: [{set: {b: {add: [var.b, 1]}}}]\n"
                                 "          after: [record: {value1: var.b}]\n",
                                 "");
  EXPECT_EQ(firstErrorAfter(one, "outputs", "outputs"),
            "pipeline.raygen[1].ray_queries: a list of 2 to 8 ray queries (each as a "
            "ray_query's fields and blocks), stepped in turn");
  EXPECT_EQ(firstErrorAfter(text, "after: [record: {value: var.a}]",
                            "after: [restart_query: {}, record: {value: var.a}]"),
            "pipeline.raygen[1].ray_queries[0].after[0].restart_query: 'restart_query' "
            "initializes the query whose candidate it decides: only in a ray_query's triangle "
            "or aabb block (not in `after`, nor in a function)");
  EXPECT_EQ(firstErrorAfter(text, "[{set: {b: {add: [var.b, 1]}}}]",
                            "[{repeat: 2, do: [restart_query: {}]}]"),
            "pipeline.raygen[1].ray_queries[1].triangle[0].do[0].restart_query: 'restart_query' "
            "inside a repeat: the block ends at a restart (the query's loop goes on with the "
            "new ray), which a repeat's loop would hold back");
  EXPECT_EQ(firstErrorAfter(text, "[{set: {b: {add: [var.b, 1]}}}]",
                            "[restart_query: {tmin: [1.0, 2.0], cull_mask: 3}]"),
            "pipeline.raygen[1].ray_queries[1].triangle[0].restart_query.tmin: restart_query "
            "tmin: expected Float, got Vec2");
  EXPECT_EQ(firstErrorAfter(text, "[{set: {b: {add: [var.b, 1]}}}]", "[restart_query: {miss: 1}]"),
            "pipeline.raygen[1].ray_queries[1].triangle[0].restart_query.miss: unknown key "
            "'miss' (expected one of: origin, direction, tmin, tmax, flags, cull_mask, tlas)");
  EXPECT_EQ(firstErrorAfter(text, "[{set: {b: {add: [var.b, 1]}}}]", "[restart_query: {tlas: 1}]"),
            "pipeline.raygen[1].ray_queries[1].triangle[0].restart_query.tlas: top level 1, but "
            "the scene has 1 (scene.instances[].tlas)");
  // The file and line of the statement too.
  const ParseResult p = parseCaseText(edited(text, "[{set: {b: {add: [var.b, 1]}}}]", "[break]"),
                                      "model/inline.yaml", "model/inline");
  ASSERT_FALSE(p.errors.empty());
  EXPECT_EQ(p.errors[0].loc.file, "model/inline.yaml");
  EXPECT_EQ(p.errors[0].loc.line, 12);
}

// Query 1's block reads what query 0's writes: the interleaving of their
// candidates would decide, so the case is refused (CaseError
// order-dependent, naming the ray_queries' file, line and field).
TEST(ModelSteppedQueries, QueriesThatShareWhatTheyWriteAreOrderDependent) {
  const std::string text =
      edited(kSteppedCase, "[{set: {b: {add: [var.b, 1]}}}]", "[{set: {b: {add: [var.a, 1]}}}]");
  Case c = parseInline(text);
  const Results r = run(c, ModelTier::Exact, 1);
  ASSERT_EQ(r.order_dependent.size(), 1u);
  EXPECT_NE(r.order_dependent[0].find("the ray_queries at model/inline.yaml:9 "
                                      "pipeline.raygen[1].ray_queries (query 0's block writes a "
                                      "local (slot 0) at model/inline.yaml:10"),
            std::string::npos)
      << r.order_dependent[0];
  EXPECT_NE(r.order_dependent[0].find("which query 1's reads at model/inline.yaml:12"),
            std::string::npos)
      << r.order_dependent[0];
  const Verdict v = compareResults(c, derivePlan(c), r, r);
  EXPECT_EQ(v.status, Status::CaseError) << v.headline();
  // Each writing only its own: no error.
  Case own = parseInline(kSteppedCase);
  EXPECT_TRUE(run(own, ModelTier::Exact, 1).order_dependent.empty());
}

// A restart that every candidate of the new ray makes again: the model
// stops restarting after kMaxQueryRestarts (as the GLSL's count does) and
// the case is a CaseError naming the restart_query.
TEST(ModelSteppedQueries, EndlessRestartsAreACaseError) {
  const std::string text = edited(kSteppedCase, "[{set: {b: {add: [var.b, 1]}}}]",
                                  "[{set: {b: {add: [var.b, 1]}}}, {restart_query: {}}]");
  Case c = parseInline(text);
  const Results r = run(c, ModelTier::Exact, 1);
  ASSERT_EQ(r.endless_restarts.size(), 1u);
  EXPECT_EQ(r.endless_restarts[0],
            "the restart_query at model/inline.yaml:12 "
            "pipeline.raygen[1].ray_queries[1].triangle[1].restart_query: launch ray 0 restarts "
            "its query more than 8 times");
  // 2 candidates, the first restarting each time: 9 runs of the first, then
  // the first's block goes on past the last restart it may make.
  EXPECT_EQ(word(r, 0, "value1"), 1u + kMaxQueryRestarts + 1u);
  const Verdict v = compareResults(c, derivePlan(c), r, r);
  EXPECT_EQ(v.status, Status::CaseError) << v.headline();
  EXPECT_NE(v.headline().find("endless-restarts"), std::string::npos) << v.headline();
}

}  // namespace stepped_queries
}  // namespace rayspec::model_test
