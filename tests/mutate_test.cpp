// Generic wrong devices (harness/mutate/): the model's own results stand in
// for a perfect device; each mutant of them must fail the comparison or carry
// the reason it may legally survive.
#include <gtest/gtest.h>

#include "fault/planted_fault.h"
#include "model/model_engine.h"
#include "model_support.h"
#include "mutate/kill_matrix.h"
#include "mutate/mutate_case.h"
#include "mutate_suite_case.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

const MutantOutcome* find(const CaseMutation& m, const std::string& name) {
  for (const MutantOutcome& o : m.mutants)
    if (o.name == name) return &o;
  return nullptr;
}

// Every ray of shared-edges is ambiguous: before, the null device, the miss
// and closest-hit counters moved by one, and `hit` perturbed all passed.
TEST(Mutate, EveryRayAmbiguousStillKillsGenericMutants) {
  const CaseMutation m = mutateSuiteCase("watertight/shared-edges");
  ASSERT_TRUE(m.judged) << m.not_judged;
  for (const char* name : {"null-device", "counter:miss+1", "counter:miss-1",
                           "counter:closesthit+1", "counter:closesthit-1", "field:hit",
                           "field:raygen_runs", "miss-and-closest-hit", "images-zeroed"}) {
    const MutantOutcome* o = find(m, name);
    ASSERT_NE(o, nullptr) << name;
    ASSERT_TRUE(o->mutation.applied) << name << ": " << o->mutation.what;
    EXPECT_TRUE(o->killed) << name << " survives: " << o->headline;
  }
}

// A counter any-hit counts depends on traversal order: its survivors carry
// that reason; no survivor of the case is left without one.
TEST(Mutate, SurvivorsCarryTheirLegalReason) {
  const CaseMutation m = mutateSuiteCase("anyhit/ignore-odd-primitives");
  ASSERT_TRUE(m.judged) << m.not_judged;
  const MutantOutcome* o = find(m, "counter:ignored+1");
  ASSERT_NE(o, nullptr);
  EXPECT_FALSE(o->killed);
  EXPECT_NE(o->legal_reason.find("traversal order"), std::string::npos) << o->legal_reason;
  for (const MutantOutcome& x : m.mutants)
    if (x.mutation.applied && !x.killed) {
      EXPECT_FALSE(x.legal_reason.empty()) << x.name << " survives with no reason";
    }
}

// TerminateOnFirstHit: a device that ignores the flag runs any-hit twice a
// ray; the declared-exact counter no longer gets the FirstHit rays' slack.
TEST(Mutate, DeclaredExactCounterHasNoSlack) {
  const CaseMutation m = mutateSuiteCase("results/terminate-on-first-hit");
  ASSERT_TRUE(m.judged) << m.not_judged;
  for (const char* name : {"counter:first_hit_anyhit+1", "counter:first_hit_anyhit-1"}) {
    const MutantOutcome* o = find(m, name);
    ASSERT_NE(o, nullptr) << name;
    EXPECT_TRUE(o->killed) << name << ": " << o->headline;
  }
}

// Every one of basic2's 20,736 rays commits the same box (all are ties):
// no two records differ, so swap-rays changes nothing and says so, found by
// one pass over the rays (the search was quadratic: 100 s in the kill matrix).
TEST(Mutate, SwapRaysOverOneAnswerIsNotApplied) {
  const CaseMutation m = mutateSuiteCase("cts-amber/basic2/without-micromap-flags");
  ASSERT_TRUE(m.judged) << m.not_judged;
  const MutantOutcome* o = find(m, "swap-rays");
  ASSERT_NE(o, nullptr);
  EXPECT_FALSE(o->mutation.applied);
  EXPECT_NE(o->mutation.what.find("no two rays with different records"), std::string::npos)
      << o->mutation.what;
}

// Where rays differ, the first ray and the first that differs from it swap.
TEST(Mutate, SwapRaysSwapsTheFirstDifferingPair) {
  const CaseMutation m = mutateSuiteCase("anyhit/ignore-odd-primitives");
  const MutantOutcome* o = find(m, "swap-rays");
  ASSERT_NE(o, nullptr);
  ASSERT_TRUE(o->mutation.applied) << o->mutation.what;
  ASSERT_EQ(o->mutation.rays.size(), 2u);
  EXPECT_LT(o->mutation.rays[0], o->mutation.rays[1]);
  EXPECT_TRUE(o->killed) << o->headline;
}

// Robustness probes: raygen's count before the trace is exact even there.
TEST(Mutate, NullDeviceFailsTheUndefinedRaysProbe) {
  const CaseMutation m = mutateSuiteCase("robustness/undefined-rays");
  ASSERT_TRUE(m.judged) << m.not_judged;
  const MutantOutcome* o = find(m, "null-device");
  ASSERT_NE(o, nullptr);
  EXPECT_TRUE(o->mutation.applied) << o->mutation.what;
  EXPECT_TRUE(o->killed) << o->headline;
}

// Eight stacked non-opaque triangles under one ray, an any-hit that leaves
// the candidate's primitive in the payload and ignores it: the last one run
// decides, among more candidates than the model orders, so the case is
// refused as order-dependent on every device.
std::string stackedLastWriter() {
  std::string vertices;
  for (int k = 0; k < 8; ++k) {
    const std::string z = std::to_string(-k);
    vertices += (k ? ", " : "") + ("[-1, -1, " + z + "], [2, -1, " + z + "], [-1, 2, " + z + "]");
  }
  return R"(rules: [R-ORDER-UNSPEC]
scene:
  blas:
    layers:
      - triangles:
          vertices: [)" +
         vertices + R"(]
        flags: []
  instances: [{blas: layers}]
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  payloads: [{words: 1}]
  raygen: [{trace: {payload: {value: 0}}}, {record: {value: payload.value}}]
  miss:
    - [count: miss]
  hit_groups:
    - any_hit: [{payload: {value: primitive_id}}, ignore]
      closest_hit: [count: chit]
outputs:
  counters: [miss, chit]
  per_ray: [value]
)";
}

// A refused case is not judged, and its legal devices are not judged either:
// each would repeat the refusal and be counted a false alarm of the judge.
TEST(Mutate, ARefusedCaseHasNoLegalDevicesToJudge) {
  const Case c = model_test::parseInline(stackedLastWriter(), "anyhit/last-writer");
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, {});
  ASSERT_EQ(model.statusText(), "ok");
  ASSERT_FALSE(model.order_dependent.empty()) << "the case must be order-dependent";
  Results device = perfectDevice(c, model);
  device.backend = "vulkan";
  const CaseMutation m = mutateCase(c, plan, device, model, 1);
  EXPECT_FALSE(m.judged);
  EXPECT_TRUE(m.legal_devices.empty()) << m.legal_devices.size() << " legal devices judged";
  EXPECT_EQ(m.not_judged.rfind("refused on every device: CaseError", 0), 0u) << m.not_judged;
}

// The matrix counts per kind and family, and a survivor with no reason is a hole.
TEST(Mutate, KillMatrixCountsHoles) {
  CaseMutation c;
  c.name = "fam/a";
  c.family = "fam";
  c.judged = true;
  MutantOutcome killed, legal, hole;
  killed.kind = legal.kind = hole.kind = "field";
  killed.mutation.applied = legal.mutation.applied = hole.mutation.applied = true;
  killed.killed = true;
  legal.legal_reason = "allowed";
  c.mutants = {killed, legal, hole};
  const KillMatrix m = buildKillMatrix({c});
  EXPECT_EQ(m.by_kind.at("field").applied, 3u);
  EXPECT_EQ(m.by_kind.at("field").killed, 1u);
  EXPECT_EQ(m.by_kind.at("field").legal, 1u);
  EXPECT_EQ(m.unexplained(), 1u);
  EXPECT_NE(killMatrixText(m).find("1 survive with no reason"), std::string::npos);
  EXPECT_NE(killMatrixJson(m, "run", "dev").find("\"unexplained_survivors\": 1"),
            std::string::npos);
}

}  // namespace
}  // namespace rayspec
