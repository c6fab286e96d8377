// The model's fault seam (model/model_fault_seam.h): built from options at
// their defaults it answers the model's own behaviour; each planted fault
// changes the answer of its own question and no other.
#include "model/model_fault_seam.h"

#include <gtest/gtest.h>

#include "case/case.h"
#include "model/model_engine.h"

namespace rayspec {
namespace {

// How many of the seam's yes/no questions answer other than the model would.
int seamDeviations(const ModelFaultSeam& s) {
  return int(s.closedTriangleInterval()) + int(s.openAabbInterval()) + int(!s.distanceOrder()) +
         int(s.stackSizeIgnored()) + int(s.positionFetchWorldSpace()) +
         int(s.transformBuiltinsSwapped()) + int(s.localsLostAcrossCalls()) +
         int(s.answersOtherwise());
}

TEST(ModelFaultSeam, DefaultOptionsAnswerTheModelsOwnBehaviour) {
  const ModelFaultSeam seam{ModelOptions{}};
  EXPECT_EQ(seamDeviations(seam), 0);
  EXPECT_FALSE(seam.answerTaken(3, 2).has_value());
  // Near to far; at the same t the smaller key first.
  EXPECT_TRUE(seam.decidedBefore(1.0, 2.0, false));
  EXPECT_FALSE(seam.decidedBefore(2.0, 1.0, true));
  EXPECT_TRUE(seam.decidedBefore(1.0, 1.0, true));
  EXPECT_FALSE(seam.decidedBefore(1.0, 1.0, false));
}

TEST(ModelFaultSeam, EachKnobChangesOnlyItsOwnAnswer) {
  ModelOptions o;
  o.faults.stack_size_ignored = true;
  EXPECT_TRUE(ModelFaultSeam(o).stackSizeIgnored());
  EXPECT_EQ(seamDeviations(ModelFaultSeam(o)), 1);
  o = {};
  o.faults.deviation = ModelDeviation::ClosedTriangleInterval;
  EXPECT_TRUE(ModelFaultSeam(o).closedTriangleInterval());
  EXPECT_EQ(seamDeviations(ModelFaultSeam(o)), 1);
  o = {};
  o.faults.deviation = ModelDeviation::OpenAabbInterval;
  EXPECT_TRUE(ModelFaultSeam(o).openAabbInterval());
  EXPECT_EQ(seamDeviations(ModelFaultSeam(o)), 1);
  o = {};
  o.faults.position_fetch_world_space = true;
  EXPECT_TRUE(ModelFaultSeam(o).positionFetchWorldSpace());
  EXPECT_EQ(seamDeviations(ModelFaultSeam(o)), 1);
  o = {};
  o.faults.transform_builtins_swapped = true;
  EXPECT_TRUE(ModelFaultSeam(o).transformBuiltinsSwapped());
  EXPECT_EQ(seamDeviations(ModelFaultSeam(o)), 1);
  o = {};
  o.faults.locals_lost_across_calls = true;
  EXPECT_TRUE(ModelFaultSeam(o).localsLostAcrossCalls());
  EXPECT_EQ(seamDeviations(ModelFaultSeam(o)), 1);
}

TEST(ModelFaultSeam, OtherOrdersDecideFarFirstOrByKey) {
  ModelOptions o;
  o.faults.order = CandidateOrder::ReverseDistance;
  const ModelFaultSeam reverse(o);
  EXPECT_FALSE(reverse.distanceOrder());
  EXPECT_TRUE(reverse.decidedBefore(2.0, 1.0, false));
  EXPECT_FALSE(reverse.decidedBefore(1.0, 2.0, true));
  o.faults.order = CandidateOrder::BuildOrder;
  const ModelFaultSeam build(o);
  EXPECT_TRUE(build.decidedBefore(5.0, 1.0, true));
  EXPECT_FALSE(build.decidedBefore(1.0, 5.0, false));
}

TEST(ModelFaultSeam, ALeakIsTakenFirstThenTheLegalAnswerModuloTheirNumber) {
  ModelOptions o;
  o.faults.legal_answer = 5;
  const ModelFaultSeam legal(o);
  EXPECT_TRUE(legal.answersOtherwise());
  ASSERT_TRUE(legal.answerTaken(3, 2).has_value());
  EXPECT_FALSE(legal.answerTaken(3, 2)->leak);
  EXPECT_EQ(legal.answerTaken(3, 2)->index, 2u);  // 5 % 3
  EXPECT_FALSE(legal.answerTaken(0, 2).has_value());
  o.faults.pass_between_edges = true;
  const ModelFaultSeam leaking(o);
  ASSERT_TRUE(leaking.answerTaken(3, 2).has_value());
  EXPECT_TRUE(leaking.answerTaken(3, 2)->leak);
  EXPECT_EQ(leaking.answerTaken(3, 2)->index, 0u);
  EXPECT_FALSE(leaking.answerTaken(3, 0)->leak);  // no leak answer: the legal one
}

// A planted query fault reaches a trace only where a --through ray-query*
// run inlines it as a query loop: every depth under ray_query, depth 2 on
// (closest-hit's and miss's traces) under ray_query_in_hit.
TEST(ModelFaultSeam, QueryFaultsReachOnlyTracesInlinedAsQueries) {
  ModelOptions o;
  o.faults.rq_confirm_ignored = true;
  Pipeline p;
  EXPECT_FALSE(ModelFaultSeam(o).inlinedQueryFaulty());
  EXPECT_FALSE(ModelFaultSeam(o, &p).inlinedQueryFaulty());
  p.ray_query = true;
  EXPECT_TRUE(ModelFaultSeam(o, &p).inlinedQuery(1).confirm_ignored);
  EXPECT_FALSE(ModelFaultSeam(ModelOptions{}, &p).inlinedQueryFaulty());
  p.ray_query = false;
  p.ray_query_in_hit = true;
  EXPECT_FALSE(ModelFaultSeam(o, &p).inlinedQuery(1).any());
  EXPECT_TRUE(ModelFaultSeam(o, &p).inlinedQuery(2).confirm_ignored);
  EXPECT_TRUE(ModelFaultSeam(o, &p).inlinedQuery(3).confirm_ignored);
  // The faults that mean nothing on an inlined loop reach none of its traces.
  for (bool ModelFaults::*knob :
       {&ModelFaults::rq_break_loses_commit, &ModelFaults::rq_function_gets_copy,
        &ModelFaults::rq_committed_reads_candidate, &ModelFaults::rq_init_keeps_committed}) {
    o = {};
    o.faults.*knob = true;
    EXPECT_FALSE(ModelFaultSeam(o, &p).inlinedQueryFaulty());
  }
}

}  // namespace
}  // namespace rayspec
