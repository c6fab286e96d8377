// What the comparison holds every device to beyond the model's one answer:
// the rules all legal answers of an ambiguous ray share, counters against
// the device's own run counts, NO_DUPLICATE_ANY_HIT per primitive, and the
// rules a finding names (compare/trace_shape.h, ambiguous_shared.cpp,
// compare_counters.cpp, compare_any_hit.cpp, finding_rules.h).
#include <gtest/gtest.h>

#include "compare/finding_rules.h"
#include "compare/trace_shape.h"
#include "compare_samples.h"

namespace rayspec {
namespace {

Stmt traceStmt() {
  Stmt s;
  s.kind = Stmt::Kind::Trace;
  return s;
}

// The sample case with raygen tracing once.
Case oneTraceCase() {
  Case c = sampleCase();
  c.pipeline.raygen = {traceStmt()};
  return c;
}

// A ray_query whose `after` records `field` (a literal: what it records is
// of no matter here).
Stmt queryStmt(const std::string& field) {
  Stmt record;
  record.kind = Stmt::Kind::Record;
  Expr one;
  one.literal = {1};
  record.assigns = {{field, one}};
  Stmt q;
  q.kind = Stmt::Kind::RayQuery;
  q.else_ = {record};
  return q;
}

// The sample case with raygen tracing once, then running a ray query that
// records `field` after it.
Case traceThenQueryCase(const std::string& field) {
  Case c = oneTraceCase();
  c.pipeline.raygen.push_back(queryStmt(field));
  return c;
}

TEST(TraceShape, OneTraceFromRaygen) {
  Case c = oneTraceCase();
  EXPECT_TRUE(traceShape(c).single_trace);
  EXPECT_TRUE(traceShape(c).hit_runs_closest_hit);
  c.pipeline.hit_groups[0].closest_hit->push_back(traceStmt());  // recursion: more traces on a hit
  EXPECT_FALSE(traceShape(c).single_trace);
  Case skip = oneTraceCase();
  skip.rays.defaults.flags = kRaySkipClosestHit;
  EXPECT_FALSE(traceShape(skip).hit_runs_closest_hit);
}

// Ray queries count: one that records a hit field may have written the
// record's after the trace (several traversals), one that records another
// field not; a query in closest-hit is a query all the same.
TEST(TraceShape, RayQueriesCount) {
  const Case value = traceThenQueryCase("value");
  EXPECT_EQ(traceShape(value).ray_queries, 1u);
  EXPECT_TRUE(traceShape(value).single_trace);  // a query runs no shader
  EXPECT_FALSE(traceShape(value).several_traces);
  EXPECT_TRUE(traceShape(traceThenQueryCase("primitive_id")).several_traces);
  Case in_hit = oneTraceCase();
  in_hit.pipeline.hit_groups[0].closest_hit->push_back(queryStmt("hit"));
  EXPECT_EQ(traceShape(in_hit).ray_queries, 1u);
  EXPECT_TRUE(traceShape(in_hit).several_traces);
  // What a query's answer may reach: from the query on, in raygen alone.
  Case later = traceThenQueryCase("value");
  Stmt record = queryStmt("value1").else_[0];
  later.pipeline.raygen.push_back(record);
  EXPECT_EQ(queryReachedFields(later), (std::set<std::string>{"value", "value1"}));
  later.pipeline.raygen.push_back(traceStmt());  // a trace after it: its shaders' fields too
  EXPECT_EQ(queryReachedFields(later), std::nullopt);
  EXPECT_EQ(queryReachedFields(in_hit), std::nullopt);
  EXPECT_EQ(queryReachedFields(oneTraceCase()), std::nullopt);
}

TEST(TraceShape, CountersThatFollowOneStagesRuns) {
  Case c = oneTraceCase();
  auto sources = counterSources(c);
  ASSERT_TRUE(sources.count("miss"));
  EXPECT_EQ(sources.at("miss").run_field, "miss_runs");
  EXPECT_EQ(sources.at("ahit").run_field, "any_hit_runs");
  // Counted inside an if: no longer once per run.
  Stmt cond;
  cond.kind = Stmt::Kind::If;
  cond.then_ = {count("chit")};
  c.pipeline.hit_groups[0].closest_hit = Program{cond};
  EXPECT_FALSE(counterSources(c).count("chit"));
  EXPECT_FALSE(countedByProgramsAlone(c, "chit"));
  EXPECT_TRUE(countedByProgramsAlone(c, "miss"));
}

TEST(CompareShared, CountersMustAgreeWithTheDevicesOwnRecords) {
  const Case c = oneTraceCase();
  Results d = sampleResults("vulkan");
  d.counters["ahit"] = 3;  // any_hit_runs total 2: any-hit is informational, but the records say 2
  const Verdict v = compareResults(c, samplePlan(c), d, sampleResults("model"));
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_TRUE(findingNames(v, Status::Fail, "the counter and the records disagree"))
      << v.headline();
}

// A ray through a shared edge: every legal answer hits, runs raygen once and
// one closest-hit. Before, a device that ran nothing there passed.
TEST(CompareShared, AmbiguousRaysKeepWhatEveryAnswerShares) {
  const Case c = oneTraceCase();
  Results m = sampleResults("model");
  // Both triangles of the edge at the model's t (2.0).
  m.ambiguous.push_back({0, AmbiguityReason::Edge, {{true, 0, 0, 0, 2.0}, {true, 0, 0, 1, 2.0}}});
  Results legal = sampleResults("vulkan");
  setUint(legal, 0, "primitive_id", 1);
  legal.images[0].texels[0] = 1;
  EXPECT_EQ(compareResults(c, samplePlan(c), legal, m).status, Status::Pass);
  Results no_raygen = legal;
  setUint(no_raygen, 0, "raygen_runs", 0);
  EXPECT_TRUE(findingNames(compareResults(c, samplePlan(c), no_raygen, m), Status::Fail,
                           "raygen did not run once"));
  Results both = legal;
  setUint(both, 0, "miss_runs", 1);
  countFromRecords(both);
  EXPECT_TRUE(
      findingNames(compareResults(c, samplePlan(c), both, m), Status::Fail, "R-MISS-XOR-CHIT"));
  Results nothing = legal;  // neither miss nor closest-hit, though every answer runs one
  setUint(nothing, 0, "closest_hit_runs", 0);
  countFromRecords(nothing);
  EXPECT_TRUE(
      findingNames(compareResults(c, samplePlan(c), nothing, m), Status::Fail, "R-MISS-XOR-CHIT"));
  Results far = legal;  // the t of no legal hit
  setFloat(far, 0, "hit_t", 2.5f);
  EXPECT_TRUE(findingNames(compareResults(c, samplePlan(c), far, m), Status::Fail, "hit_t"));
  // A legal answer behind the edge (the any-hit ignored the other triangle)
  // has a t of its own: a device taking it at that t passes (issue 43).
  Results behind_model = m;
  behind_model.ambiguous.back().candidates.push_back({true, 0, 0, 2, 2.5});
  Results behind = far;
  setUint(behind, 0, "primitive_id", 2);
  behind.images[0].texels[0] = 2;
  EXPECT_FALSE(
      findingNames(compareResults(c, samplePlan(c), behind, behind_model), Status::Fail, "hit_t"))
      << compareResults(c, samplePlan(c), behind, behind_model).headline();
  Results image = legal;  // the image must show the device's own record
  image.images[0].texels[0] = 0;
  EXPECT_TRUE(
      findingNames(compareResults(c, samplePlan(c), image, m), Status::Fail, "own records"));
}

// A ray in a triangle's plane (the model's own answer a miss, a legal hit
// on primitive 1 anywhere across it) with no replays (a hit at no one t:
// legal_replays.cpp). Where raygen alone traces, its record's hit fields
// are that trace's: another primitive, or primitive 1 at a t outside the
// span, fails. Where the miss shader traces too, they may be its child's
// (fuzz/seed-120385 ray 5 on NVIDIA 580: the miss's child hit instance 0):
// held to what the answers share, no false Fail.
TEST(CompareShared, AnInPlaneRayWithoutReplaysIsHeldToItsOwnTrace) {
  Results m = sampleResults("model");  // ray 0's record: primitive 0 at t 2.0
  m.ambiguous.push_back({0, AmbiguityReason::InPlane, {{false, 0, 0, 0}, {true, 0, 0, 1, 2.0}}});
  const Case one = oneTraceCase();
  const Results child = sampleResults("vulkan");  // the model's record, primitive 0
  EXPECT_TRUE(findingNames(compareResults(one, samplePlan(one), child, m), Status::Fail,
                           "not one of its legal answers"));
  Results outside = child;  // primitive 1, at a t outside the in-plane span
  setUint(outside, 0, "primitive_id", 1);
  outside.images[0].texels[0] = 1;
  setFloat(outside, 0, "hit_t", 5.0f);
  EXPECT_TRUE(
      findingNames(compareResults(one, samplePlan(one), outside, m), Status::Fail, "hit_t"));
  Case traced = oneTraceCase();
  traced.pipeline.miss[0].push_back(traceStmt());  // the miss shader traces a child ray
  const Verdict v = compareResults(traced, samplePlan(traced), child, m);
  EXPECT_FALSE(findingNames(v, Status::Fail, "not one of its legal answers")) << v.headline();
}

// A ray whose ambiguous traversal is the ray query after raygen's one trace
// (fuzz/seed-150445 ray 3 and 150663 ray 6 on Mesa 26.2.6: the trace missed,
// every legal answer of the query hit): the trace's miss is no answer of
// the query's. Before, the judge read the query's answer from the trace's
// miss ("missed, and no legal answer is a miss"): the model's own record
// failed. Every field the query cannot reach is still the model's: a trace
// that hit there fails, as raygen run twice does; and an ambiguity of the
// trace itself is still read from the trace's fields.
TEST(CompareShared, ARayQuerysAmbiguityIsHeldToTheFieldsItCannotReach) {
  const Case c = traceThenQueryCase("value");
  Results m = sampleResults("model");  // ray 2: the trace missed
  RayAmbiguity query{2, AmbiguityReason::Order, {{true, 0, 0, 1, 2.0}}};
  query.from_query = true;
  m.ambiguous.push_back(query);
  const Results legal = sampleResults("vulkan");  // the model's own record
  const Verdict v = compareResults(c, samplePlan(c), legal, m);
  EXPECT_EQ(v.status, Status::Pass) << v.headline();
  Results hit = legal;  // the trace, clear, hit
  setUint(hit, 2, "hit", 1);
  EXPECT_TRUE(findingNames(compareResults(c, samplePlan(c), hit, m), Status::Fail,
                           "writes it neither in its blocks nor after"));
  Results twice = legal;
  setUint(twice, 2, "raygen_runs", 2);
  EXPECT_TRUE(
      findingNames(compareResults(c, samplePlan(c), twice, m), Status::Fail, "raygen did not run"));
  Results trace_model = m;  // the trace's own ambiguity: its miss is no legal answer
  trace_model.ambiguous[0].from_query = false;
  EXPECT_TRUE(findingNames(compareResults(c, samplePlan(c), legal, trace_model), Status::Fail,
                           "no legal answer is a miss"));
}

// The miss counter follows miss runs: only a ray that may hit or miss lets
// it move; the edge ray above (two hits) does not.
TEST(CompareShared, CounterSlackOnlyWhereLegalAnswersDiffer) {
  const Case c = oneTraceCase();
  Results m = sampleResults("model");
  m.ambiguous.push_back({0, AmbiguityReason::Edge, {{true, 0, 0, 0}, {true, 0, 0, 1}}});
  EXPECT_EQ(counterSlack(c, "miss", m).above, 0u);
  m.ambiguous.push_back({1, AmbiguityReason::TmaxTie, {{true, 0, 0, 1}, {false, 0, 0, 0}}});
  EXPECT_EQ(counterSlack(c, "miss", m).above, 1u);
  Case declared = c;
  declared.outputs.counter_modes["miss"] = "exact";
  EXPECT_EQ(counterSlack(declared, "miss", m), CounterSlack{});
}

// NO_DUPLICATE_ANY_HIT per primitive: any-hit twice on one primitive fails,
// even where the total per ray is right.
TEST(CompareShared, AnyHitRepeatOnOnePrimitiveFails) {
  Case c = oneTraceCase();
  Geometry g;
  g.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}};
  g.flags = kGeometryNoDuplicateAnyHit;
  c.scene.blases.push_back({"two", {g}, {}});
  Instance in;
  in.blas = 0;
  c.scene.instances.push_back(in);
  Results m = sampleResults("model");
  Results d = sampleResults("vulkan");
  setUint(d, 0, "any_hit_slots", 1u << anyHitSlot(0, 0, 0));
  setUint(d, 0, "any_hit_repeats", 1u << anyHitSlot(0, 0, 0));
  const Verdict v = compareResults(c, samplePlan(c), d, m);
  EXPECT_TRUE(findingNames(v, Status::Fail, "ran twice on one primitive")) << v.headline();
  c.scene.blases[0].geometries[0].flags = 0;  // duplicates allowed
  EXPECT_FALSE(findingNames(compareResults(c, samplePlan(c), d, m), Status::Fail, "ran twice"));
}

TEST(FindingRules, AFindingNamesOneRuleAndKeepsTheClaimsItEvidences) {
  // The one claim the field evidences, the field's own rule not claimed.
  FindingRule r = findingRule(rulesEvidencedByField("hit_kind"), {"R-FACE-DET", "R-RECURSION"},
                              "R-HITKIND-TRI");
  EXPECT_EQ(r.rule, "R-FACE-DET");
  EXPECT_EQ(r.evidence, (std::vector<std::string>{"R-FACE-DET"}));
  // No claim evidenced: the field's own rule.
  r = findingRule(rulesEvidencedByField("depth"), {"R-FACE-DET"}, "R-RECURSION");
  EXPECT_EQ(r.rule, "R-RECURSION");
  EXPECT_TRUE(r.evidence.empty());
  // The field's own rule claimed: it, whatever else is claimed.
  r = findingRule(rulesEvidencedByField("hit_kind"), {"R-HITKIND-TRI", "R-FACE-DET"},
                  "R-HITKIND-TRI");
  EXPECT_EQ(r.rule, "R-HITKIND-TRI");
  EXPECT_EQ(r.evidence, (std::vector<std::string>{"R-HITKIND-TRI", "R-FACE-DET"}));
  // Several claims evidenced, the own rule not among them: the one the value
  // speaks of itself, not how the pipeline is built and run; else the own rule.
  r = findingRule(rulesEvidencedByField("hit"), {"R-AS-BUILD", "R-BUILTIN"}, "R-MISS-XOR-CHIT");
  EXPECT_EQ(r.rule, "R-BUILTIN");
  EXPECT_EQ(r.evidence, (std::vector<std::string>{"R-AS-BUILD", "R-BUILTIN"}));
  r = findingRule(rulesEvidencedByField("value3"), {"R-RQ-VALUES", "R-RQ-COMMIT"}, "R-PAYLOAD");
  EXPECT_EQ(r.rule, "R-PAYLOAD");
  // A counter (no rule of its own): the claims it evidences, joined.
  r = findingRule({"R-FACE-DET", "R-INST-XFORM"}, {"R-INST-XFORM", "R-FACE-DET"}, "counter");
  EXPECT_EQ(r.rule, "R-FACE-DET/R-INST-XFORM");
  const Case c = oneTraceCase();
  const auto callable = rulesEvidencedByCounter(c, "miss");
  EXPECT_NE(std::find(callable.begin(), callable.end(), "R-MISS-XOR-CHIT"), callable.end());
}

// Issue 61: "R-RQ-CANDIDATES/R-RQ-COMMIT/R-RQ-VALUES: per-ray field 'value3'
// differs" named every claim of the case. The headline names the field's
// rule; the finding still names each claim for a proof of it.
TEST(FindingRules, AFieldOfACaseClaimingThreeRulesNamesOne) {
  Case c = sampleCase();
  c.rules = {"R-RQ-CANDIDATES", "R-RQ-COMMIT", "R-RQ-VALUES"};
  c.outputs.per_ray.push_back("value3");
  const Results m = sampleResults("model");
  Results d = sampleResults("vulkan");
  setUint(d, 1, "value3", 7);
  const Verdict v = compareResults(c, samplePlan(c), d, m);
  ASSERT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_EQ(v.headline().rfind("Fail: R-PAYLOAD: per-ray field 'value3' differs", 0), 0u)
      << v.headline();
  const auto f_it = std::find_if(v.findings.begin(), v.findings.end(), [](const Finding& f) {
    return f.message.find("'value3'") != std::string::npos;
  });
  ASSERT_NE(f_it, v.findings.end()) << v.headline();
  const Finding& f = *f_it;
  EXPECT_EQ(f.rule, "R-PAYLOAD");
  for (const std::string& rule : c.rules) EXPECT_TRUE(findingNames(f, rule)) << rule;
  EXPECT_FALSE(findingNames(f, "R-RECURSION"));
  // One claim of the three, and it is named.
  c.rules = {"R-RQ-VALUES"};
  const Verdict one = compareResults(c, samplePlan(c), d, m);
  EXPECT_EQ(one.headline().rfind("Fail: R-RQ-VALUES: per-ray field 'value3' differs", 0), 0u)
      << one.headline();
}

}  // namespace
}  // namespace rayspec
