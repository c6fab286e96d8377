// A double hit (R-WATERTIGHT, a "should"): a device that runs any-hit on
// several triangles closing around a shared edge or vertex (lavapipe 25.0.7
// on fuzz seed 170852: three of a closed fan of six, each ignored) leaves a
// record none of the legal answers leaves. The model replays each set of
// those triangles in the orders whose effects differ (model/double_hits.cpp)
// and the judge takes such a record as a QualityWarning; a record no set of
// them leaves, or one on a clear ray, still fails.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <set>
#include <string>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "model_support.h"

namespace rayspec::double_hit_test {
namespace {

using namespace model_test;

// A regular closed fan of six (primitive k between rim angles 60k and
// 60(k + 1) degrees) whose any-hit sets bit primitive_id of the payload and
// ignores the hit: ray 0 through the centre vertex, ray 1 through the spoke
// at 0 degrees (primitives 0 and 5), ray 2 through primitive 0's centroid.
const char* kFanCase = R"(rules: [R-WATERTIGHT]
scene:
  blas:
    fan:
      - triangles: {fan: {triangles: 6, radius: 1, center: [0, 0, 0]}}
        flags: []
  instances:
    - {blas: fan}
rays:
  list:
    - {origin: [0, 0, 5], direction: [0, 0, -1]}
    - {origin: [0.5, 0, 5], direction: [0, 0, -1]}
    - {origin: [0.5, 0.28867513, 5], direction: [0, 0, -1]}
pipeline:
  payloads: [{words: 1}]
  raygen: [{trace: {payload: {word0: 0}}}, {record: {value8: payload.word0}}]
  miss:
    - [{count: miss}]
  hit_groups:
    - any_hit:
        - count: ahit
        - payload: {word0: {bit_or: [payload.word0, {shl: [1, primitive_id]}]}}
        - ignore
      closest_hit: [{count: chit}]
outputs:
  per_ray: [value8]
  counters: [miss, ahit, {chit: informational}]
)";

struct FanRun {
  Case c;
  Plan plan;
  Results model;
};

// `flags`: the fan geometry's.
FanRun fanRun(const std::string& flags = "[]") {
  std::string yaml = kFanCase;
  yaml.replace(yaml.find("flags: []"), 9, "flags: " + flags);
  FanRun j;
  j.c = parseInline(yaml, "model/double-hit-fan");
  j.plan = derivePlan(j.c);
  j.model = runOnModel(j.c, j.plan, ModelOptions{});
  return j;
}

// The device that recorded `value8` on `ray`, the model's elsewhere: the
// record (and counter moves) of the model's replay that leaves it, legal or
// double hit; where none does, the model's own record with that value8 and
// as many any-hit runs as it has bits (counted too).
Verdict judgeValue(const FanRun& j, uint32_t ray, uint32_t value8) {
  Results device = perfectDevice(j.c, j.model);
  uint32_t* rec = &device.records[static_cast<size_t>(ray) * recordWords()];
  const uint32_t at = findRecordField("value8")->offset;
  const uint32_t runs = findRecordField("any_hit_runs")->offset;
  const RayAmbiguity* a = ambiguityOf(j.model, ray);
  if (a)
    for (const auto* list : {&a->replays, &a->double_replays})
      for (const LegalReplay& r : *list)
        if (r.record[at] == value8) {
          std::copy(r.record.begin(), r.record.end(), rec);
          for (const auto& [name, move] : r.counter_moves)
            device.counters[name] =
                static_cast<uint64_t>(static_cast<int64_t>(device.counters[name]) + move);
          return compareResults(j.c, j.plan, device, j.model);
        }
  device.counters["ahit"] += static_cast<uint64_t>(std::popcount(value8)) - rec[runs];
  rec[at] = value8;
  rec[runs] = static_cast<uint32_t>(std::popcount(value8));
  return compareResults(j.c, j.plan, device, j.model);
}

bool hasFinding(const Verdict& v, Status s, const std::string& rule, const std::string& text) {
  return std::any_of(v.findings.begin(), v.findings.end(), [&](const Finding& f) {
    return f.status == s && f.rule == rule && f.message.find(text) != std::string::npos;
  });
}

bool failsSaying(const Verdict& v, const std::string& text) {
  return v.status == Status::Fail &&
         std::any_of(v.findings.begin(), v.findings.end(), [&](const Finding& f) {
           return f.status == Status::Fail && f.message.find(text) != std::string::npos;
         });
}

// The values of value8 a list of replays leaves.
std::set<uint32_t> values(const std::vector<LegalReplay>& replays) {
  std::set<uint32_t> out;
  for (const LegalReplay& r : replays) out.insert(r.record[findRecordField("value8")->offset]);
  return out;
}

TEST(DoubleHit, TheModelReplaysEverySetOfTheTrianglesClosingAroundTheRay) {
  const FanRun j = fanRun();
  ASSERT_EQ(j.model.statusText(), "ok");
  const RayAmbiguity* vertex = ambiguityOf(j.model, 0);
  const RayAmbiguity* edge = ambiguityOf(j.model, 1);
  ASSERT_TRUE(vertex && edge);
  EXPECT_EQ(ambiguityOf(j.model, 2), nullptr);
  EXPECT_EQ(vertex->reason, AmbiguityReason::Vertex);
  // Every set of one or more of the six is left by a legal replay or by a
  // double hit (each triangle alone is legal; so is a second one's any-hit
  // run where the candidate orders say so: model_exact_orders.cpp), every
  // set of three or more by a double hit alone.
  const std::set<uint32_t> legal = values(vertex->replays);
  const std::set<uint32_t> doubled = values(vertex->double_replays);
  for (uint32_t v = 1; v < 64; ++v) {
    EXPECT_NE(legal.count(v) + doubled.count(v), 0u) << v;
    if (std::popcount(v) == 1) {
      EXPECT_EQ(legal.count(v), 1u) << v;
    }
    if (std::popcount(v) >= 3) {
      EXPECT_EQ(doubled.count(v), 1u) << v;
    }
  }
  EXPECT_EQ(legal.size() + doubled.size(), 63u);
  // The spoke's two triangles: both any-hits are a legal answer already.
  EXPECT_EQ(values(edge->replays), (std::set<uint32_t>{1u, 32u, 1u | 32u}));
}

TEST(DoubleHit, OneTriangleOfTheFanPassesAndSeveralAreAQualityWarning) {
  const FanRun j = fanRun();
  const Verdict own = compareResults(j.c, j.plan, perfectDevice(j.c, j.model), j.model);
  EXPECT_EQ(own.status, Status::Pass) << own.headline();
  // Each legal answer at the vertex: one triangle's any-hit.
  for (uint32_t k = 0; k < 6; ++k) {
    const Verdict v = judgeValue(j, 0, 1u << k);
    EXPECT_EQ(v.status, Status::Pass) << k << ": " << v.headline();
  }
  // Three of the fan's triangles, as lavapipe ran them on seed 170852.
  const Verdict three = judgeValue(j, 0, (1u << 1) | (1u << 2) | (1u << 4));
  EXPECT_EQ(three.status, Status::QualityWarning) << three.headline();
  EXPECT_TRUE(hasFinding(three, Status::QualityWarning, "R-WATERTIGHT", "double hit"));
  // All six.
  EXPECT_EQ(judgeValue(j, 0, 63u).status, Status::QualityWarning);
}

// With NO_DUPLICATE_ANY_HIT_INVOCATION (the ahit counter exact): the same
// QualityWarning, and more any-hit runs counted than the records show fail.
TEST(DoubleHit, UnderNoDuplicateAnyHitTooAndCountsBeyondItFail) {
  const FanRun j = fanRun("[no_duplicate_any_hit]");
  const Verdict three = judgeValue(j, 0, (1u << 1) | (1u << 2) | (1u << 4));
  EXPECT_EQ(three.status, Status::QualityWarning) << three.headline();
  // The model's records with three any-hit runs more counted than they show.
  Results device = perfectDevice(j.c, j.model);
  const Verdict own = compareResults(j.c, j.plan, device, j.model);
  EXPECT_EQ(own.status, Status::Pass) << own.headline();
  device.counters["ahit"] += 3;
  EXPECT_EQ(compareResults(j.c, j.plan, device, j.model).status, Status::Fail);
}

TEST(DoubleHit, AValueNoSetOfTheTrianglesLeavesStillFails) {
  const FanRun j = fanRun();
  const std::string none = "per-ray field 'value8' is what none of the legal answers";
  // The spoke at 0 degrees and primitive 2, far from it.
  const Verdict far = judgeValue(j, 1, 1u | 4u);
  EXPECT_EQ(far.status, Status::Fail) << far.headline();
  EXPECT_TRUE(failsSaying(far, none)) << far.headline();
  // A bit of no primitive of the fan, beside two of it.
  const Verdict stray = judgeValue(j, 0, 1u | 2u | 64u);
  EXPECT_EQ(stray.status, Status::Fail) << stray.headline();
  EXPECT_TRUE(failsSaying(stray, none)) << stray.headline();
  // Two triangles on a ray through one triangle's inside: no shared edge.
  const Verdict clear = judgeValue(j, 2, 1u | 2u);
  EXPECT_TRUE(failsSaying(clear, "per-ray field 'value8' differs from the model on clear rays"))
      << clear.headline();
}

}  // namespace
}  // namespace rayspec::double_hit_test
