// Ray query vocabulary beyond one loop per query (issue 55): a break out of
// the proceed loop, a query passed to a function, top levels named by a
// dynamic index. Each in every tier, with the fault that breaks it and the
// errors of its parse and check paths.
#include "model_suite_runs.h"

namespace rayspec::model_test {
namespace query_vocabulary {  // named: the unity build joins model_ray_query_test's helpers

TEST(ModelRayQueryVocabulary, BreakLeavesTheLoopKeepingWhatIsCommitted) {
  for (ModelTier tier : kTiers) {
    const Results r = runSuiteCase("ray-query/leave-loop-early", tier);
    EXPECT_EQ(column(r, "value", 2), (V{1, 1})) << modelTierName(tier);   // committed
    EXPECT_EQ(column(r, "value1", 2), (V{1, 1})) << modelTierName(tier);  // one block ran
    EXPECT_EQ(column(r, "value2", 2), (V{0, 0}));  // a repeat's break: the loop goes on
    EXPECT_EQ(column(r, "value3", 2), (V{3, 3}));
    EXPECT_EQ(column(r, "value4", 2), (V{1, 1}));  // continue skips instance 0
    EXPECT_FLOAT_EQ(fword(r, 0, "color"), 11.0f);
    EXPECT_EQ(column(r, "value5", 2), (V{0, 0}));  // a nested after's break leaves the outer
    EXPECT_EQ(column(r, "value6", 2), (V{1, 1}));
    EXPECT_TRUE(r.undefined.empty());
  }
}

TEST(ModelRayQueryVocabulary, AFunctionDecidesTheCallersQuery) {
  for (ModelTier tier : kTiers) {
    const Results r = runSuiteCase("ray-query/query-in-function", tier);
    EXPECT_EQ(column(r, "value", 2), (V{1, 1})) << modelTierName(tier);
    EXPECT_EQ(column(r, "value1", 2), (V{11, 12}));
    EXPECT_FLOAT_EQ(fword(r, 0, "color"), 11.0f);
    EXPECT_FLOAT_EQ(fword(r, 1, "color"), 12.0f);
  }
}

TEST(ModelRayQueryVocabulary, ADynamicIndexNamesEachRaysTopLevel) {
  for (ModelTier tier : kTiers) {
    const Results r = runSuiteCase("ray-query/dynamic-tlas-index", tier);
    EXPECT_EQ(column(r, "value", 4), (V{10, 11, 12, 10})) << modelTierName(tier);
    EXPECT_EQ(column(r, "value1", 4), (V{0, 1, 2, 0}));
    EXPECT_EQ(column(r, "value2", 4), (V{11, 12, 10, 11}));
    EXPECT_EQ(column(r, "value3", 4), (V{12, 10, 11, 12}));
  }
}

TEST(ModelRayQueryVocabulary, FaultKnobsChangeTheirCases) {
  ModelFaults f;
  auto differs = [&](const char* name) {
    const Results good = runSuiteCase(name, ModelTier::Exact);
    const Results bad = runSuiteCase(name, ModelTier::Exact, f);
    return good.records != bad.records;
  };
  f.rq_break_loses_commit = true;
  EXPECT_TRUE(differs("ray-query/leave-loop-early"));
  EXPECT_FALSE(differs("ray-query/terminate-middle"));  // no break leaves a loop there
  f = {};
  f.rq_function_gets_copy = true;
  EXPECT_TRUE(differs("ray-query/query-in-function"));
  EXPECT_FALSE(differs("ray-query/confirm-nearest"));
}

const char* kQueryCase =
    "rules: [R-RQ-COMMIT]\n"
    "scene:\n"
    "  blas: {t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]}\n"
    "  instances: [{blas: t}, {blas: t, tlas: 0x1}]\n"
    "rays: {list: [{origin: [0.2, 0.2, 1], direction: [0, 0, -1]}]}\n"
    "pipeline:\n"
    "  functions:\n"
    "    pick: {query: true, do: [confirm]}\n"
    "  raygen:\n"
    "    - ray_query:\n"
    "        tlas: 1\n"
    "        triangle: [confirm, break]\n"
    "        after: [record: {value: committed.type}]\n"
    "outputs: {per_ray: [value]}\n";

TEST(ModelRayQueryVocabulary, ParseAndCheckErrorsNameTheField) {
  const std::string text = kQueryCase;
  EXPECT_EQ(firstErrorAfter(text, "tlas: 1", "tlas: launch_id_x"), "(no error)");
  EXPECT_EQ(firstErrorAfter(text, "tlas: 1", "tlas: {add: [launch_id_x, 0.5]}"),
            "pipeline.raygen[0].ray_query.tlas: operator 'add': arguments are (Uint, Float); need "
            "the same numeric type, or a Float with a vector, or a sized vector with a scalar "
            "of its component type");
  EXPECT_EQ(firstErrorAfter(text, "tlas: 1", "tlas: 1.0"),
            "pipeline.raygen[0].ray_query.tlas: expected an unsigned integer (decimal or 0x hex)");
  EXPECT_EQ(firstErrorAfter(text, "tlas: 1", "tlas: {mul: [0.5, 2.0]}"),
            "pipeline.raygen[0].ray_query.tlas: ray_query tlas: expected Uint, got Float");
  // A break in `after` leaves no loop; in a function, none of the caller's.
  EXPECT_EQ(firstErrorAfter(text, "after: [record", "after: [break, record"),
            "pipeline.raygen[0].ray_query.after[0]: 'break' outside a repeat");
  EXPECT_EQ(firstErrorAfter(text, "triangle: [confirm, break]", "triangle: [invoke: pick]"),
            "(no error)");
  EXPECT_EQ(firstErrorAfter(text, "after: [record", "after: [invoke: pick, record"),
            "pipeline.functions.pick.do[0]: 'confirm' commits a triangle candidate: only in a "
            "ray_query's triangle block");
  EXPECT_EQ(firstErrorAfter(text, "  raygen:\n", "  raygen:\n    - invoke: pick\n"),
            "pipeline.raygen[0].invoke: invoke pick: the function takes a ray query (query: true); "
            "invoke it in a ray_query's triangle, aabb or after block");
  EXPECT_EQ(firstErrorAfter(text, "query: true", "query: yes"),
            "pipeline.functions.pick.query: expected true or false, not 'yes'");
  std::string invoked = text;
  invoked.replace(invoked.find("[confirm, break]"), 16, "[invoke: pick]");
  EXPECT_EQ(firstErrorAfter(invoked, "do: [confirm]", "do: [confirm, break]"),
            "pipeline.functions.pick.do[1]: 'break' outside a repeat");
}

}  // namespace query_vocabulary
}  // namespace rayspec::model_test
