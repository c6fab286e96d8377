// The model's ray_query statements (model/model_query.cpp): candidates,
// commits, termination and getters, in every tier; generate outside its
// interval is undefined; the fault seam's ray query knobs each change what
// a case observes.
#include "model_suite_runs.h"

namespace rayspec::model_test {
namespace {

TEST(ModelRayQuery, OffersNonOpaqueCandidatesInTheInterval) {
  for (ModelTier tier : kTiers) {
    const Results r = runSuiteCase("ray-query/candidates-count", tier);
    // Bits of the instances offered: 0..2 non-opaque; 3 opaque, committed.
    EXPECT_EQ(column(r, "value", 6), (V{7, 3, 6, 0, 15, 0})) << modelTierName(tier);
    EXPECT_EQ(column(r, "value1", 6), (V{1, 0, 1, 1, 0, 0}));
    EXPECT_EQ(word(r, 0, "value2"), 3u);
    EXPECT_EQ(word(r, 3, "value2"), 0u);  // opaque flag: the nearest, committed unoffered
    EXPECT_TRUE(r.ambiguous.empty());
  }
}

TEST(ModelRayQuery, ConfirmCommitsTheClosestAndGettersReadIt) {
  for (ModelTier tier : kTiers) {
    const Results r = runSuiteCase("ray-query/confirm-nearest", tier);
    EXPECT_EQ(column(r, "value", 5), (V{1, 1, 1, 1, 0}));
    EXPECT_EQ(column(r, "value1", 4), (V{0, 0, 1, 2}));
    EXPECT_EQ(column(r, "value3", 4), (V{7, 7, 8, 9}));
    EXPECT_EQ(column(r, "value4", 4), (V{1, 1, 0, 1}));  // instance 1 is turned over
    EXPECT_FLOAT_EQ(fword(r, 0, "color"), 10.0f);
    EXPECT_FLOAT_EQ(fword(r, 2, "color"), 0.5f);
  }
}

// An ambiguity of a ray query says so (RayAmbiguity::from_query): the
// judge reads its answer from no trace's fields. tie-two-instances ray 0: a
// t tie of the query's, in raygen, which traces nothing.
TEST(ModelRayQuery, AQuerysAmbiguityIsNotedAsTheQuerys) {
  const Results r = runSuiteCase("ray-query/tie-two-instances", ModelTier::Exact);
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(r.ambiguous[0].ray, 0u);
  EXPECT_TRUE(r.ambiguous[0].from_query);
}

TEST(ModelRayQuery, GenerateCommitsAtTheEndsOfItsInterval) {
  const Results r = runSuiteCase("ray-query/generate-at-tmin", ModelTier::Exact);
  EXPECT_EQ(column(r, "value", 4), (V{2, 2, 2, 0}));
  EXPECT_EQ(column(r, "value2", 3), (V{5, 6, 6}));
  EXPECT_EQ(column(r, "value3", 3), (V{0, 0, 1}));
  EXPECT_EQ(column(r, "value4", 3), (V{0, 0, 1}));
  EXPECT_FLOAT_EQ(fword(r, 0, "color"), 0.5f);
  EXPECT_FLOAT_EQ(fword(r, 2, "color"), 2.25f);
  const Results at = runSuiteCase("ray-query/generate-at-committed-t", ModelTier::Exact);
  EXPECT_EQ(column(at, "value", 2), (V{2, 2}));
  EXPECT_FLOAT_EQ(fword(at, 0, "color"), 10.0f);
  EXPECT_FLOAT_EQ(fword(at, 1, "color"), 20.0f);
  EXPECT_TRUE(at.undefined.empty());
}

TEST(ModelRayQuery, GenerateOutsideItsIntervalIsUndefined) {
  Case c = suiteCaseFile("ray-query/generate-at-committed-t");
  // tmin + 9.5 then 0.25: below tmin (0.5) on every ray.
  c.pipeline.raygen[0].then_[1].then_[1].t.literal = {0.25};
  c.pipeline.raygen[0].then_[1].then_[1].t.kind = Expr::Kind::Literal;
  c.pipeline.raygen[0].then_[1].then_[1].t.type = ValueType::Float;
  const Results r = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_EQ(r.undefined.size(), 2u);
  EXPECT_EQ(r.undefined[0].reason, UndefinedReason::GenerateOutsideInterval);
  EXPECT_NE(r.undefined[0].what.find("outside [tmin"), std::string::npos) << r.undefined[0].what;
}

TEST(ModelRayQuery, ACommittedValueWithNothingCommittedIsUndefined) {
  Case c = suiteCaseFile("ray-query/confirm-nearest");
  // after: record committed.t whether or not anything is committed.
  Stmt read;
  read.kind = Stmt::Kind::Record;
  Expr t = builtinExpr(kBiQCommittedT, {});
  read.assigns.emplace_back("value5", t);
  c.pipeline.raygen[0].else_.push_back(read);
  c.outputs.per_ray.push_back("value5");
  const Results r = runOnModel(c, derivePlan(c), ModelOptions{});
  // Only ray 4 (between the triangles: nothing to confirm) reads it undefined.
  ASSERT_EQ(r.undefined.size(), 1u);
  EXPECT_EQ(r.undefined[0].ray, 4u);
  EXPECT_EQ(r.undefined[0].reason, UndefinedReason::QueryNothingCommitted);
}

// ray-query/position-fetch: the nearer instance 0 is offered and kept as a
// candidate's; instance 1 (turned, scaled, moved) is committed. Both read
// object-space vertices, whatever the transforms (R-POSITION-FETCH).
TEST(ModelRayQuery, PositionFetchReadsTheCandidatesAndTheCommittedTriangle) {
  for (ModelTier tier : kTiers) {
    const Results r = runSuiteCase("ray-query/position-fetch", tier);
    EXPECT_EQ(column(r, "value", 5), (V{1, 1, 1, 1, 0})) << modelTierName(tier);
    EXPECT_EQ(column(r, "value2", 4), (V{1, 1, 1, 1}));
    // Ray 0: the candidate of instance 0 is triangle 0, its second vertex
    // (0.75, -0.75); instance 1's triangle 0 has third vertex (0.75, 0.75).
    EXPECT_EQ(fword(r, 0, "color2", 0), 0.75f);
    EXPECT_EQ(fword(r, 0, "color2", 1), -0.75f);
    EXPECT_EQ(fword(r, 0, "color2", 3), 0.75f);
    // Ray 1 commits triangle 1 (0, 2, 3): first vertex (-0.75, -0.75, 0.25), second (0.75, 0.75).
    EXPECT_EQ(fword(r, 1, "color", 0), -0.75f);
    EXPECT_EQ(fword(r, 1, "color", 2), 0.25f);
    EXPECT_EQ(fword(r, 1, "hit_position", 1), 0.75f);
    EXPECT_TRUE(r.undefined.empty());
  }
  ModelFaults world;
  world.position_fetch_world_space = true;
  const Results f = runSuiteCase("ray-query/position-fetch", ModelTier::Exact, world);
  EXPECT_NE(fword(f, 1, "color", 2), 0.25f);  // instance 1 is moved 2 down
}

TEST(ModelRayQuery, PositionsOfACommittedBoxAreUndefined) {
  // A box generated at its entry is committed; the after block then reads
  // the committed positions, which only a triangle has.
  const Case c = parseInline(
      "rules: [R-RQ-VALUES]\n"
      "scene:\n"
      "  blas:\n"
      "    box: [{aabbs: [[-1, -1, 1, 1, 1, 2]]}]\n"
      "  instances: [{blas: box}]\n"
      "rays:\n"
      "  list: [{origin: [0, 0, 5], direction: [0, 0, -1]}]\n"
      "pipeline:\n"
      "  raygen:\n"
      "    - ray_query:\n"
      "        aabb: [generate: 3.0]\n"
      "        after:\n"
      "          - if: {eq: [committed.type, 2]}\n"
      "            then: [record: {hit_position: committed.vertex_position0}]\n"
      "outputs:\n"
      "  per_ray: [hit_position]\n");
  const Results r = runOnModel(c, derivePlan(c), ModelOptions{});
  ASSERT_EQ(r.undefined.size(), 1u);
  EXPECT_EQ(r.undefined[0].reason, UndefinedReason::QueryPositionsOfBox);
  EXPECT_NE(r.undefined[0].what.find("vertex_position0"), std::string::npos);
}

TEST(ModelRayQuery, TerminateAndFirstHitEndTraversal) {
  for (ModelTier tier : kTiers) {
    const Results t = runSuiteCase("ray-query/terminate-middle", tier);
    EXPECT_EQ(column(t, "value", 3), (V{0, 0, 0}));   // nothing committed
    EXPECT_EQ(column(t, "value1", 3), (V{0, 0, 0}));  // no block after the terminate
    EXPECT_EQ(column(t, "value2", 3), (V{1, 1, 0}));
    EXPECT_EQ(word(t, 2, "value3"), 96u);
    const Results f = runSuiteCase("ray-query/query-first-hit", tier);
    EXPECT_EQ(column(f, "value", 2), (V{1, 2}));
    EXPECT_EQ(column(f, "value1", 2), (V{0, 0}));
    EXPECT_EQ(column(f, "value3", 2), (V{1, 3}));
    EXPECT_TRUE(f.ambiguous.empty()) << modelTierName(tier);
  }
}

TEST(ModelRayQuery, NestedQueriesAndLoopsKeepTheirOwnState) {
  const Results n = runSuiteCase("ray-query/two-queries", ModelTier::Exact);
  EXPECT_EQ(column(n, "value1", 2), (V{2, 2}));
  EXPECT_EQ(column(n, "value2", 2), (V{0x555, 0x555}));
  EXPECT_NEAR(fword(n, 0, "color", 0), 2.9f, 1e-5);
  EXPECT_NEAR(fword(n, 0, "color", 2), 2.9f, 1e-5);
  EXPECT_FLOAT_EQ(fword(n, 0, "color", 3), 12.0f);
  const Results l = runSuiteCase("ray-query/query-in-loop", ModelTier::Exact);
  EXPECT_EQ(column(l, "value", 2), (V{1, 1}));
  EXPECT_EQ(column(l, "value1", 2), (V{16, 16}));
  EXPECT_FLOAT_EQ(fword(l, 0, "color", 3), 1.25f);
}

TEST(ModelRayQuery, ClosestHitAndMissRunQueriesInTheirOwnFrame) {
  for (ModelTier tier : kTiers) {
    const Results r = runSuiteCase("ray-query/query-in-hit-and-miss", tier);
    EXPECT_EQ(column(r, "value", 3), (V{31, 1, 233})) << modelTierName(tier);
    EXPECT_FLOAT_EQ(fword(r, 0, "color", 0), 2.0f);
    EXPECT_FLOAT_EQ(fword(r, 0, "color", 1), -1.5f);  // the query's origin: the hit position
    EXPECT_FLOAT_EQ(fword(r, 2, "color", 0), 15.0f);
  }
}

TEST(ModelRayQuery, CandidateAndCommittedGettersReadTheirOwnHits) {
  const Results r = runSuiteCase("ray-query/candidate-vs-committed", ModelTier::Exact);
  EXPECT_EQ(column(r, "value", 2), (V{2, 2}));
  EXPECT_EQ(column(r, "value3", 2), (V{2, 2}));   // the box's SBT offset
  EXPECT_EQ(column(r, "value6", 2), (V{4, 4}));   // the triangle's custom index
  EXPECT_EQ(column(r, "value7", 2), (V{0, 0}));   // turned over: back face
  EXPECT_EQ(column(r, "value9", 2), (V{0, 0}));   // committed read in the block: the box
  EXPECT_EQ(column(r, "value10", 2), (V{9, 9}));  // candidate types 0 and 1
  EXPECT_FLOAT_EQ(fword(r, 0, "color", 0), 15.0f);
  EXPECT_FLOAT_EQ(fword(r, 0, "color", 2), 10.0f);
}

// Each knob of the fault seam changes what its case observes (the planted
// faults of fault/mutate_ray_query.cpp stand on them).
TEST(ModelRayQuery, FaultKnobsChangeTheirCases) {
  ModelFaults f;
  auto differs = [&](const char* name) {
    const Results good = runSuiteCase(name, ModelTier::Exact);
    const Results bad = runSuiteCase(name, ModelTier::Exact, f);
    return good.records != bad.records;
  };
  f = {};
  f.rq_init_keeps_committed = true;
  EXPECT_TRUE(differs("ray-query/query-in-loop"));
  f = {};
  f.rq_opaque_offered = true;
  EXPECT_TRUE(differs("ray-query/opaque-not-offered"));
  f = {};
  f.rq_confirm_ignored = true;
  EXPECT_TRUE(differs("ray-query/confirm-nearest"));
  f = {};
  f.rq_generate_ignored = true;
  EXPECT_TRUE(differs("ray-query/generate-at-tmin"));
  f = {};
  f.rq_terminate_ignored = true;
  EXPECT_TRUE(differs("ray-query/terminate-middle"));
  EXPECT_TRUE(differs("ray-query/query-first-hit"));
  f = {};
  f.rq_committed_reads_candidate = true;
  EXPECT_TRUE(differs("ray-query/candidate-vs-committed"));
  EXPECT_FALSE(differs("ray-query/confirm-nearest"));  // no committed read beside a candidate
  f = {};
  f.rq_custom_index_is_instance_id = true;
  EXPECT_TRUE(differs("ray-query/confirm-nearest"));
}

TEST(ModelRayQuery, ParseErrorsNameTheField) {
  const std::string text =
      "rules: [R-RQ-COMMIT]\n"
      "scene:\n"
      "  blas: {t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]}\n"
      "  instances: [{blas: t}]\n"
      "rays: {list: [{origin: [0.2, 0.2, 1], direction: [0, 0, -1]}]}\n"
      "pipeline:\n"
      "  raygen:\n"
      "    - ray_query:\n"
      "        triangle: [confirm]\n"
      "        after: [record: {value: committed.type}]\n"
      "outputs: {per_ray: [value]}\n";
  EXPECT_EQ(firstErrorAfter(text, "triangle: [confirm]", "triangle: [confirm]"), "(no error)");
  EXPECT_EQ(firstErrorAfter(text, "triangle: [confirm]", "aabb: [confirm]"),
            "pipeline.raygen[0].ray_query.aabb[0]: 'confirm' commits a triangle candidate: only "
            "in a ray_query's triangle block");
  EXPECT_EQ(firstErrorAfter(text, "triangle: [confirm]", "sides: [confirm]"),
            "pipeline.raygen[0].ray_query.sides: unknown key 'sides' (expected one of: origin, "
            "direction, tmin, tmax, flags, cull_mask, tlas, triangle, aabb, after, "
            "order_dependent)");
  EXPECT_NE(firstErrorAfter(text, "value: committed.type", "value: candidate.t")
                .find("after traversal it is undefined"),
            std::string::npos);
}

}  // namespace
}  // namespace rayspec::model_test
