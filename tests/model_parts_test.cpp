// Two of the Machine's parts on their own (model/model_machine.h): the
// shader binding table as the model reads it (ModelSbt) and the launch
// ray's state (LaunchState), which the exact tier's what-if runs save and
// restore and which keeps the first R-UB reason of a ray.
#include "model/launch_state.h"
#include "model/model_sbt.h"
#include "model_support.h"

namespace rayspec::model_test {
namespace {

const std::string kTwoGroups = std::string("rules: [R-SBT-HIT]\n") + kTriangleHitAndMiss +
                               R"(pipeline:
  raygen:
    - trace: {}
  miss:
    - [count: miss]
  hit_groups:
    - closest_hit: [count: first]
    - closest_hit: [count: second]
  callables:
    - [count: calls]
outputs:
  counters: [miss, first, second, calls]
)";

TEST(ModelParts, WithoutAnSbtEachRegionHasOneRecordPerGroupInOrder) {
  const Case c = parseInline(kTwoGroups);
  const ModelSbt sbt(c);
  ASSERT_EQ(sbt.hitCount(), 2u);
  ASSERT_EQ(sbt.miss().size(), 1u);
  ASSERT_EQ(sbt.callables().size(), 1u);
  TraceRay r;
  r.sbt_stride = 1;
  EXPECT_EQ(sbt.hit(0, 0, r)->group, std::optional<uint32_t>(0));
  r.sbt_offset = 1;
  EXPECT_EQ(sbt.hit(0, 0, r)->group, std::optional<uint32_t>(1));
  r.sbt_offset = 2;
  EXPECT_EQ(sbt.hit(0, 0, r), nullptr);  // beyond the region (R-UB for the caller)
}

TEST(ModelParts, HitIndexTakesTheLowBitsOfEachTerm) {
  Case c = parseInline(kTwoGroups);
  c.scene.instances[0].sbt_offset = 0x1000003;  // 24 bits: 3
  const ModelSbt sbt(c);
  TraceRay r;
  r.sbt_offset = 0x12;  // 4 bits: 2
  r.sbt_stride = 0x15;  // 4 bits: 5
  EXPECT_EQ(sbt.hitIndex(0, 2, r), 3u + 2u * 5u + 2u);
}

TEST(ModelParts, ASavedLaunchStateComesBackWholeAndTheFirstUndefinedReasonStays) {
  const Case c = parseInline(kTwoGroups);
  const Plan plan = derivePlan(c);
  ModelShared shared;
  shared.c = &c;
  shared.plan = &plan;
  const ModelSbt sbt(c);
  std::vector<uint32_t> records(2 * recordWords(), 0);
  LaunchState st(shared, sbt, records.data());
  st.startRay(1);
  EXPECT_EQ(st.rec, records.data() + recordWords());
  const LaunchState::Saved before = st.save();
  st.bumpRuns(kRunsRaygen);
  st.counters[0] += 4;
  st.error = "model: something";
  EXPECT_EQ(records[recordWords() + st.runsOffset(kRunsRaygen)], 1u);
  st.restore(before);
  EXPECT_EQ(records[recordWords() + st.runsOffset(kRunsRaygen)], 0u);
  EXPECT_EQ(st.counters[0], 0u);
  EXPECT_EQ(st.error, "");
  st.markUndefined(UndefinedReason::DivisionByZero, "first");
  st.markUndefined(UndefinedReason::RecursionTooDeep, "second");
  ASSERT_EQ(st.undefined.size(), 1u);
  EXPECT_EQ(st.undefined[0].ray, 1u);
  EXPECT_EQ(st.undefined[0].reason, UndefinedReason::DivisionByZero);
  st.startRay(0);  // a new launch ray may be undefined again
  EXPECT_FALSE(st.ray_undefined);
}

}  // namespace
}  // namespace rayspec::model_test
