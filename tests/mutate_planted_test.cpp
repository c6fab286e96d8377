// The ray query faults in the kill matrix (mutate/planted_mutants.h): each
// planted in the model's own answers and judged; a survivor is legal only
// where every ray it changed is undefined, never because a ray is ambiguous.
#include <gtest/gtest.h>

#include "model/model_engine.h"
#include "mutate/kill_matrix.h"
#include "mutate/mutate_case.h"
#include "mutate_suite_case.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

// Every order of the three triangles and the box commits the closest: the
// faults that commit beyond it or drop the second confirm are killed.
TEST(MutatePlanted, QueryFaultsKilledOnConfirmEveryCandidate) {
  const CaseMutation m = mutateSuiteCase("ray-query/confirm-every-candidate");
  ASSERT_TRUE(m.judged) << m.not_judged;
  for (const char* fault :
       {"query-commit-beyond-committed-t", "query-confirm-only-first", "query-confirm-ignored",
        "query-candidate-type-swapped", "query-custom-index-is-instance-id"}) {
    const MutantOutcome* o = findPlanted(m, fault);
    ASSERT_NE(o, nullptr) << fault;
    EXPECT_EQ(o->kind, "planted-query");
    ASSERT_TRUE(o->mutation.applied) << fault << ": " << o->mutation.what;
    EXPECT_TRUE(o->killed) << fault << " survives: " << o->headline;
  }
  // Nothing reads the front face: the fault does not apply.
  const MutantOutcome* face = findPlanted(m, "query-front-face-inverted");
  ASSERT_NE(face, nullptr);
  EXPECT_FALSE(face->mutation.applied);
}

// The case's one ray is an exact tie (ambiguous): a fault that survives
// there is a hole, not a legal survivor, and the matrix counts it so.
TEST(MutatePlanted, ASurvivorOnAnAmbiguousRayIsAHole) {
  const CaseMutation m = mutateSuiteCase("ray-query/tie-two-instances");
  ASSERT_TRUE(m.judged) << m.not_judged;
  const MutantOutcome* o = findPlanted(m, "query-custom-index-is-instance-id");
  ASSERT_NE(o, nullptr);
  ASSERT_TRUE(o->mutation.applied) << o->mutation.what;
  EXPECT_TRUE(o->killed || o->legal_reason.empty())
      << "a legal reason on an ambiguous ray: " << o->legal_reason;
  const KillMatrix k = buildKillMatrix({m});
  if (!o->killed) {
    EXPECT_GE(k.unexplained(), 1u);
  }
}

// A --through ray-query run inlines every trace as a ray query loop: the
// query faults break those loops (ModelFaultSeam::inlinedQuery) and are
// killed there. The case as written runs no query for them to break.
TEST(MutatePlanted, QueryFaultsBreakTracesInlinedAsQueries) {
  const char* faults[] = {"query-confirm-ignored", "query-generate-ignored",
                          "query-candidate-type-swapped"};
  const CaseMutation as_written = mutateSuiteCase("anyhit/terminate-accepts");
  ASSERT_TRUE(as_written.judged) << as_written.not_judged;
  for (const char* fault : faults) {
    const MutantOutcome* o = findPlanted(as_written, fault);
    ASSERT_NE(o, nullptr) << fault;
    EXPECT_FALSE(o->mutation.applied) << fault << ": " << o->mutation.what;
  }
  const CaseMutation m = mutateSuiteCase("anyhit/terminate-accepts", FeaturePath::RayQuery);
  ASSERT_TRUE(m.judged) << m.not_judged;
  for (const char* fault : faults) {
    const MutantOutcome* o = findPlanted(m, fault);
    ASSERT_NE(o, nullptr) << fault;
    ASSERT_TRUE(o->mutation.applied) << fault << ": " << o->mutation.what;
    EXPECT_TRUE(o->killed) << fault << " survives: " << o->headline;
  }
}

// TerminateOnFirstHit's exact any-hit count: a loop that goes on after its
// first commit (far to near) runs the any-hit on every layer; one whose
// commits keep the interval ends on the farthest layer.
TEST(MutatePlanted, InlinedTerminateAndIntervalFaultsKilled) {
  const CaseMutation m = mutateSuiteCase("results/terminate-on-first-hit", FeaturePath::RayQuery);
  ASSERT_TRUE(m.judged) << m.not_judged;
  for (const char* fault : {"query-terminate-ignored", "query-commit-beyond-committed-t",
                            "query-confirm-only-first", "query-confirm-ignored"}) {
    const MutantOutcome* o = findPlanted(m, fault);
    ASSERT_NE(o, nullptr) << fault;
    ASSERT_TRUE(o->mutation.applied) << fault << ": " << o->mutation.what;
    EXPECT_TRUE(o->killed) << fault << " survives: " << o->headline;
  }
}

// Layers nearer than the terminating one are all ignored: a loop that goes
// on after the terminate (far to near) commits what a legal order commits,
// and runs any-hit as the order (0, 3, 2, 1) does. A survivor that shows only
// what a legal device shows is legal, not a hole (mutate/legal_output.h).
TEST(MutatePlanted, ASurvivorALegalDeviceMatchesIsLegal) {
  const CaseMutation m =
      mutateSuiteCase("control/any-hit-functions/loop-stop-1", FeaturePath::RayQuery);
  ASSERT_TRUE(m.judged) << m.not_judged;
  const MutantOutcome* o = findPlanted(m, "query-terminate-ignored");
  ASSERT_NE(o, nullptr);
  ASSERT_TRUE(o->mutation.applied) << o->mutation.what;
  EXPECT_FALSE(o->killed) << o->headline;
  EXPECT_EQ(o->legal_reason.rfind("R-ORDER-UNSPEC", 0), 0u) << o->legal_reason;
}

// Every ray misses whether or not its boxes run their intersection
// programs; the color every any-hit sets shows a device that took them for
// triangles (and ran none): the fault is killed, not an equivalent.
TEST(MutatePlanted, CandidateTypeSwappedKilledWhereBoxesAllMiss) {
  const CaseMutation m = mutateSuiteCase("anyhit/accumulate/aabbs-allowed", FeaturePath::RayQuery);
  ASSERT_TRUE(m.judged) << m.not_judged;
  const MutantOutcome* o = findPlanted(m, "query-candidate-type-swapped");
  ASSERT_NE(o, nullptr);
  ASSERT_TRUE(o->mutation.applied) << o->mutation.what;
  EXPECT_TRUE(o->killed) << o->headline;
  for (const LegalDevice& d : m.legal_devices)
    EXPECT_FALSE(d.false_alarm) << d.name << ": " << d.headline;
}

}  // namespace
}  // namespace rayspec
