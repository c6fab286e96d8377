// An ambiguous ray held to its legal answers as a whole (issue 55 item 3,
// issue 62 classes 1 and 4): the model replays each legal answer through the
// launch ray (model/legal_replays.h), and the judge takes a record that is
// one of them, whatever fields it holds, and fails one that is none, even
// where every field is one no legal answer writes alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "model_support.h"
#include "parse/parse_case.h"

namespace rayspec {
namespace {

using namespace model_test;

// Two instances of one triangle at one place (custom index 5 and 6): ray 0
// meets both at t = 10 exactly, a tie (R-TIE); ray 1 misses. Closest-hit
// records the custom index and counts it by its value.
const char* kTieCase = R"(rules: [R-TIE]
scene:
  blas:
    tri:
      - triangles: {vertices: [[-5, -5, 0], [5, -5, 0], [0, 5, 0]]}
  instances:
    - {blas: tri, custom_index: 5}
    - {blas: tri, custom_index: 6}
rays:
  list:
    - {origin: [0.1, 0.2, 10], direction: [0, 0, -1]}
    - {origin: [50, 0.2, 10], direction: [0, 0, -1]}
pipeline:
  miss:
    - - record: {value: 1}
  hit_groups:
    - closest_hit:
        - record: {value: instance_custom_index, primitive_id: primitive_id}
        - if: {eq: [instance_custom_index, 5]}
          then: [{count: five}]
          else: [{count: six}]
outputs:
  per_ray: [value, primitive_id]
  counters: [five, six]
)";

struct TieRun {
  Case c;
  Plan plan;
  Results model;
};

TieRun tieRun() {
  TieRun j;
  j.c = parseInline(kTieCase, "model/replay-tie");
  j.plan = derivePlan(j.c);
  j.model = runOnModel(j.c, j.plan, ModelOptions{});
  return j;
}

uint32_t* recordOf(Results& r, uint32_t ray) {
  return &r.records[static_cast<size_t>(ray) * recordWords()];
}

bool failsSaying(const Verdict& v, const std::string& text) {
  return v.status == Status::Fail &&
         std::any_of(v.findings.begin(), v.findings.end(), [&](const Finding& f) {
           return f.status == Status::Fail && f.message.find(text) != std::string::npos;
         });
}

TEST(LegalReplays, EachAnswerOfATieIsReplayedThroughClosestHit) {
  TieRun j = tieRun();
  ASSERT_EQ(j.model.statusText(), "ok");
  ASSERT_EQ(j.model.ambiguous.size(), 1u);
  const RayAmbiguity& a = j.model.ambiguous[0];
  EXPECT_EQ(a.reason, AmbiguityReason::TTie);
  ASSERT_EQ(a.replays.size(), 2u);
  std::vector<uint32_t> values;
  for (const LegalReplay& r : a.replays)
    values.push_back(r.record[findRecordField("value")->offset]);
  std::sort(values.begin(), values.end());
  EXPECT_EQ(values, (std::vector<uint32_t>{5, 6}));
  // The other answer moves one count from one counter to the other.
  const LegalReplay& other = a.replays[1];
  EXPECT_EQ(other.counter_moves.size(), 2u);
  // The model's own record and counters are its own answer's.
  EXPECT_EQ(word(j.model, 0, "value"), a.replays[0].record[findRecordField("value")->offset]);
  EXPECT_EQ(j.model.counters["five"] + j.model.counters["six"], 1u);
}

TEST(LegalReplays, EitherAnswerPassesAndNeitherFails) {
  TieRun j = tieRun();
  const Results own = perfectDevice(j.c, j.model);
  const Verdict v0 = compareResults(j.c, j.plan, own, j.model);
  EXPECT_EQ(v0.status, Status::Pass) << v0.headline();

  // The other legal answer, record and counters together: Pass.
  Results other = own;
  const LegalReplay& r = j.model.ambiguous[0].replays[1];
  std::copy(r.record.begin(), r.record.end(), recordOf(other, 0));
  for (const auto& [name, move] : r.counter_moves)
    other.counters[name] = static_cast<uint64_t>(static_cast<int64_t>(other.counters[name]) + move);
  EXPECT_EQ(compareResults(j.c, j.plan, other, j.model).status, Status::Pass);

  // A custom index neither instance has (no identity field tells the
  // answers apart, so only the replays can judge it): Fail.
  Results wrong = own;
  recordOf(wrong, 0)[findRecordField("value")->offset] = 0;
  EXPECT_TRUE(failsSaying(compareResults(j.c, j.plan, wrong, j.model),
                          "is what none of the legal answers of a numerically ambiguous ray"));
}

TEST(LegalReplays, CountersMoveOnlyAsTheReplaysMoveThem) {
  TieRun j = tieRun();
  const Results own = perfectDevice(j.c, j.model);
  // Neither counted (the old slack of one per ambiguous ray let this pass).
  Results none = own;
  none.counters["five"] = none.counters["six"] = 0;
  const Verdict v = compareResults(j.c, j.plan, none, j.model);
  EXPECT_EQ(v.status, Status::Fail);
  // Both counted: the one ray has one answer, never two.
  Results both = own;
  both.counters["five"] = both.counters["six"] = 1;
  EXPECT_EQ(compareResults(j.c, j.plan, both, j.model).status, Status::Fail);
}

// Issue 62 class 1: the launch's closest-hit records the primitive (1) and
// a nested trace's closest-hit the instance of another hit, a tie of two
// instances of primitive 0. The record mixes two hits and fits no legal
// answer of the nested trace by its identity fields (the old judge failed
// the model's own results so); it is whole when it is one of the replays:
// the model's own run judged as a device passes, and so does each legal
// answer, and a third instance id fails.
TEST(LegalReplays, IdentityFieldsOfTwoTracesAreJudgedAsOneRecord) {
  Case c = parseInline(R"(rules: [R-TIE]
scene:
  blas:
    tri:
      - triangles: {vertices: [[40, -5, 0], [50, -5, 0], [45, 5, 0], [-5, -5, 0], [5, -5, 0], [0, 5, 0]]}
    two:
      - triangles: {vertices: [[-5, -5, -4], [5, -5, -4], [0, 5, -4]]}
  instances:
    - {blas: tri}
    - {blas: two}
    - {blas: two}
rays:
  list:
    - {origin: [0.1, 0.2, 10], direction: [0, 0, -1]}
pipeline:
  max_recursion: 2
  miss:
    - - record: {value: 1}
  hit_groups:
    - closest_hit:
        - if: {eq: [depth, 1]}
          then:
            - record: {primitive_id: primitive_id}
            - trace: {origin: [0.1, 0.2, -1], direction: [0, 0, -1]}
          else:
            - record: {instance_id: instance_id}
outputs:
  per_ray: [primitive_id, instance_id, value]
)",
                       "model/replay-mixed");
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{});
  ASSERT_EQ(model.statusText(), "ok");
  ASSERT_EQ(model.ambiguous.size(), 1u);
  ASSERT_GE(model.ambiguous[0].replays.size(), 2u);
  EXPECT_EQ(compareResults(c, plan, perfectDevice(c, model), model).status, Status::Pass);
  EXPECT_EQ(word(model, 0, "primitive_id"), 1u);
  std::set<uint32_t> instances;
  for (const LegalReplay& r : model.ambiguous[0].replays) {
    Results d = perfectDevice(c, model);
    std::copy(r.record.begin(), r.record.end(), recordOf(d, 0));
    instances.insert(r.record[findRecordField("instance_id")->offset]);
    EXPECT_EQ(compareResults(c, plan, d, model).status, Status::Pass);
  }
  EXPECT_EQ(instances, (std::set<uint32_t>{1, 2}));
  Results third = perfectDevice(c, model);
  recordOf(third, 0)[findRecordField("instance_id")->offset] = 0;
  EXPECT_EQ(compareResults(c, plan, third, model).status, Status::Fail);
}

// Issue 62 class 4: both answers of the tie record primitive 0, so the
// identity fields cannot tell them apart; the old judge took the device's
// record for the model's own answer and held its custom index to the
// model's. The other answer, recorded whole, passes.
TEST(LegalReplays, IdentityFieldsEveryAnswerSharesDoNotPickTheAnswer) {
  TieRun j = tieRun();
  ASSERT_EQ(j.model.ambiguous.size(), 1u);
  ASSERT_EQ(j.model.ambiguous[0].replays.size(), 2u);
  for (const LegalReplay& r : j.model.ambiguous[0].replays)
    EXPECT_EQ(r.record[findRecordField("primitive_id")->offset], 0u);
  Results other = perfectDevice(j.c, j.model);
  const LegalReplay& r = j.model.ambiguous[0].replays[1];
  std::copy(r.record.begin(), r.record.end(), recordOf(other, 0));
  for (const auto& [name, move] : r.counter_moves)
    other.counters[name] = static_cast<uint64_t>(static_cast<int64_t>(other.counters[name]) + move);
  const Verdict v = compareResults(j.c, j.plan, other, j.model);
  EXPECT_EQ(v.status, Status::Pass) << v.headline();
}

// One ambiguous ray (ray 0) of a case, judged both ways by the pairs of two
// record fields: every legal answer the model replays is a device that passes,
// and the pairs they leave are `legal`; each pair of `wrong` (a record of a
// replay with that first field, its second field changed) is a device that fails.
using FieldPair = std::pair<uint32_t, uint32_t>;

void expectLegalPairs(const Case& c, const std::string& first_field,
                      const std::string& second_field, const std::set<FieldPair>& legal,
                      const std::vector<FieldPair>& wrong) {
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{});
  ASSERT_EQ(model.statusText(), "ok");
  ASSERT_EQ(model.ambiguous.size(), 1u);
  const uint32_t first = findRecordField(first_field)->offset;
  const uint32_t second = findRecordField(second_field)->offset;
  std::set<FieldPair> answers;
  for (const LegalReplay& r : model.ambiguous[0].replays) {
    answers.insert({r.record[first], r.record[second]});
    Results d = perfectDevice(c, model);
    std::copy(r.record.begin(), r.record.end(), recordOf(d, 0));
    const Verdict v = compareResults(c, plan, d, model);
    EXPECT_EQ(v.status, Status::Pass) << v.headline();
  }
  EXPECT_EQ(answers, legal);
  for (const auto& [f, wrong_value] : wrong) {
    Results d = perfectDevice(c, model);
    for (const LegalReplay& r : model.ambiguous[0].replays)
      if (r.record[first] == f) std::copy(r.record.begin(), r.record.end(), recordOf(d, 0));
    recordOf(d, 0)[second] = wrong_value;
    EXPECT_TRUE(failsSaying(compareResults(c, plan, d, model),
                            "is what none of the legal answers of a numerically ambiguous ray"))
        << f << " " << wrong_value;
  }
}

Case libraryCase(const std::string& name) {
  const ParseResult p =
      parseCaseFile(RAYSPEC_SOURCE_DIR "/cases/" + name + ".yaml", RAYSPEC_SOURCE_DIR "/cases");
  EXPECT_TRUE(p.value.has_value()) << name;
  return p.value.value_or(Case{});
}

// Fuzz seed 100492 on NVIDIA, reduced (cases/precision/tie-after-far-any-hit):
// instance 1's far triangle met first (any-hit +1), then the tie of both
// instances' near triangles, instance 1's kept (any-hit +16): value 17 with
// instance 1, a legal answer the model's orders left out (each tie went to
// the smaller key). Every (instance, value) the specification allows is a
// replay and passes; instance 1 without its own any-hit's 16 is none and fails.
TEST(LegalReplays, ATieAfterAFarAnyHitMayKeepEitherInstance) {
  expectLegalPairs(libraryCase("precision/tie-after-far-any-hit"), "instance_id", "value",
                   {{0, 0}, {0, 1}, {0, 16}, {0, 17}, {1, 16}, {1, 17}}, {{1, 0}, {1, 1}, {1, 33}});
}

// Fuzz seed 20094 on lavapipe 25.0.7, reduced
// (cases/precision/vertex-after-far-any-hit): the far triangle met first
// (any-hit +1), then the near triangle's corner, a vertex of no closed fan
// the model misses, hit: value 1 with geometry 0, a legal answer the model's
// orders left out (the corner forced a hit only where it came first). Every
// (geometry, value) the specification allows is a replay and passes; the far
// triangle without its any-hit, or the corner with it run twice, fails.
TEST(LegalReplays, AVertexAfterAFarAnyHitKeepsItsEffect) {
  expectLegalPairs(libraryCase("precision/vertex-after-far-any-hit"), "geometry_index", "value",
                   {{0, 0}, {0, 1}, {1, 1}}, {{1, 0}, {0, 2}});
}

// Two instances of one box at one place, each reporting at its top face (t
// 9.5 from the same arithmetic: a tie, R-TIE); each any-hit folds its
// instance into the payload (value * 4 + instance + 1), so its order shows.
// Whichever reports first commits; the other's report lands on t = tmax,
// inside the closed interval (R-CAND-AABB-CLOSED), and may be dropped before
// its any-hit (a step past tmax by rounding), or confirmed, its any-hit run,
// then replacing or kept out (Ray Closest Hit Determination: "may be set as
// the current closest hit or dropped"). Ray 1 misses.
const char* kReportTieCase = R"(rules: [R-TIE]
scene:
  blas:
    box:
      - aabbs: [[-1, -1, -0.5, 1, 1, 0.5]]
        flags: [no_duplicate_any_hit]
  instances:
    - {blas: box}
    - {blas: box}
rays:
  list:
    - {origin: [0, 0, 10], direction: [0, 0, -1]}
    - {origin: [50, 0, 10], direction: [0, 0, -1]}
pipeline:
  raygen: [{trace: {payload: {value: 0}}}, {record: {value: payload.value}}]
  miss:
    - [record: {hit: 0}]
  hit_groups:
    - intersection: [report: {t: {sub: [{z: object_ray_origin}, {z: aabb_max}]}, kind: 1}]
      any_hit: [payload: {value: {add: [{mul: [payload.value, 4]}, {add: [instance_id, 1]}]}}]
      closest_hit: [record: [hit, instance_id]]
outputs:
  per_ray: [hit, instance_id, value]
)";

// Each order of the two reports, and each way of the second: kept out
// before its any-hit (the first's alone: 0 with 1, 1 with 2), confirmed and
// kept out (0 with 6, 1 with 9: the model listed these as none before), or
// confirmed and replacing (1 with 6, 0 with 9). Each is a replay and passes;
// an instance with a value its any-hits cannot leave fails.
TEST(LegalReplays, AReportAtTheCommittedTRunsItsAnyHitThenMayBeKeptOut) {
  expectLegalPairs(parseInline(kReportTieCase, "model/replay-report-tie"), "instance_id", "value",
                   {{0, 1}, {1, 2}, {0, 6}, {1, 9}, {1, 6}, {0, 9}}, {{0, 2}, {1, 1}, {0, 5}});
}

}  // namespace
}  // namespace rayspec
