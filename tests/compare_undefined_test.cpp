// Rays with undefined behaviour (R-UB, Results::undefined): left out of every
// comparison, reported apart, and what they make of a case's status.
#include <gtest/gtest.h>

#include "compare/compare_results.h"
#include "compare/counter_modes.h"
#include "compare/undefined_behaviour.h"
#include "compare_samples.h"

namespace rayspec {
namespace {

// The sample results of the model with ray 1 undefined (a hit record out of range).
Results modelWithUndefinedRay1() {
  Results m = sampleResults("model");
  m.undefined.push_back(
      {1, UndefinedReason::HitRecordOutOfRange, "pipeline.raygen[0].trace: hit record 3 of 1"});
  return m;
}

Case probeCase() {
  Case c = sampleCase();
  c.rules = {"R-UB", "R-MISS-XOR-CHIT"};
  return c;
}

const Finding* findingOf(const Verdict& v, const std::string& rule) {
  for (const Finding& f : v.findings)
    if (f.rule == rule) return &f;
  return nullptr;
}

std::string allFindings(const Verdict& v) {
  std::string s = v.headline() + "\n";
  for (const Finding& f : v.findings)
    s += std::string(statusName(f.status)) + " " + f.rule + ": " + f.message + "\n";
  return s;
}

// A device that got ray 1 wrong in every way a comparison looks at: its
// primitive, its image pixel, its any-hit runs.
Results deviceWrongOnRay(uint32_t ray) {
  Results d = sampleResults("vulkan");
  setUint(d, ray, "primitive_id", 9);
  d.images[0].texels[ray] = 9;
  setUint(d, ray, "any_hit_runs", 5);
  return d;
}

TEST(UndefinedRays, LeftOutOfRecordsImagesAndAnyHitChecks) {
  Case c = probeCase();
  // Every geometry NO_DUPLICATE_ANY_HIT triangles: the any-hit run check applies.
  Geometry g;
  g.flags = kGeometryNoDuplicateAnyHit;
  c.scene.blases.push_back({"quad", {g}, {}});
  Results m = modelWithUndefinedRay1();
  setUint(m, 1, "closest_hit_runs", 0);  // so that the any-hit check looks at ray 1
  // The same wrong answers on a clear ray fail: the records, the image and any-hit are checked
  // there.
  Results d = deviceWrongOnRay(0);
  setUint(m, 0, "closest_hit_runs", 0);
  const Verdict wrong = compareResults(c, samplePlan(c), d, m);
  EXPECT_EQ(wrong.status, Status::Fail);
  EXPECT_TRUE(findingOf(wrong, "image")) << allFindings(wrong);
  EXPECT_TRUE(findingOf(wrong, "R-AHIT-DUP")) << allFindings(wrong);
  // On the undefined ray they are never judged.
  d = deviceWrongOnRay(1);
  setUint(d, 0, "closest_hit_runs", 0);
  const Verdict v = compareResults(c, samplePlan(c), d, m);
  EXPECT_EQ(v.status, Status::Pass) << allFindings(v);
}

TEST(UndefinedRays, CountersTheyMayMoveBecomeInformational) {
  Case c = probeCase();
  // raygen: count `launches`, trace, count `after`: only `launches` is safe from the trace's
  // undefined behaviour.
  Stmt trace;
  trace.kind = Stmt::Kind::Trace;
  c.pipeline.raygen = {count("launches"), trace, count("after")};
  c.outputs.counters = {"miss", "chit", "ahit", "launches", "after"};
  EXPECT_EQ(countersUndefinedRaysMayMove(c),
            (std::set<std::string>{"miss", "chit", "ahit", "after"}));
  Results m = modelWithUndefinedRay1();
  m.counters["launches"] = 4;
  m.counters["after"] = 4;
  Results d = sampleResults("vulkan");
  d.counters = {{"miss", 7}, {"chit", 0}, {"ahit", 2}, {"launches", 4}, {"after", 1}};
  const Verdict v = compareResults(c, samplePlan(c), d, m);
  EXPECT_EQ(v.status, Status::Pass) << allFindings(v);
  bool noted = false;
  for (const Finding& f : v.findings)
    noted = noted || (f.message.find("'miss'") != std::string::npos &&
                      f.message.find("undefined behaviour") != std::string::npos);
  EXPECT_TRUE(noted) << allFindings(v);
  // A counter no undefined ray can reach stays exact.
  d.counters["launches"] = 3;
  EXPECT_EQ(compareResults(c, samplePlan(c), d, m).status, Status::Fail);
  // Without undefined rays the same counts fail.
  d.counters["launches"] = 4;
  Results clear = sampleResults("model");
  clear.counters["launches"] = 4;
  clear.counters["after"] = 4;
  EXPECT_EQ(compareResults(c, samplePlan(c), d, clear).status, Status::Fail);
}

TEST(UndefinedRays, ReportedApartByReasonWithTheFirstRaysAndWhat) {
  const std::vector<UndefinedRays> groups = groupUndefinedRays({
      {7, UndefinedReason::DivisionByZero, "pipeline.miss[0][1].record.value: uint division by 0"},
      {2, UndefinedReason::HitRecordOutOfRange, "pipeline.raygen[0].trace: hit record 3"},
      {3, UndefinedReason::HitRecordOutOfRange, "pipeline.raygen[0].trace: hit record 4"},
  });
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].reason, UndefinedReason::HitRecordOutOfRange);  // reason order
  EXPECT_EQ(groups[0].ray_count, 2u);
  EXPECT_EQ(groups[0].rays, (std::vector<uint32_t>{2, 3}));
  EXPECT_EQ(groups[0].what, "pipeline.raygen[0].trace: hit record 3");
  EXPECT_EQ(groups[1].reason, UndefinedReason::DivisionByZero);
  EXPECT_EQ(groups[1].rays, (std::vector<uint32_t>{7}));

  Results m = sampleResults("model");
  m.undefined = {
      {3, UndefinedReason::CallableOutOfRange, "pipeline.raygen[1].call.index: callable 5 of 2"},
      {2, UndefinedReason::CallableOutOfRange, "pipeline.raygen[1].call.index: callable 6 of 2"}};
  const Case c = probeCase();
  const Verdict v = compareResults(c, samplePlan(c), sampleResults("vulkan"), m);
  ASSERT_EQ(v.undefined.size(), 1u);
  EXPECT_EQ(v.undefined[0].ray_count, 2u);
  const Finding* f = findingOf(v, "R-UB");
  ASSERT_TRUE(f) << allFindings(v);
  EXPECT_EQ(f->ray_count, 2u);
  EXPECT_EQ(f->rays, (std::vector<uint32_t>{2, 3}));
  EXPECT_NE(f->message.find("callable-out-of-range 2"), std::string::npos) << f->message;
  EXPECT_NE(f->message.find("callable 5 of 2"), std::string::npos) << f->message;
}

// --- judgeUndefinedBehaviour, one test per branch ---

TEST(UndefinedBehaviourVerdict, NoUndefinedRaysLeaveTheVerdictAlone) {
  Verdict v;
  EXPECT_TRUE(
      judgeUndefinedBehaviour(sampleCase(), sampleResults("vulkan"), sampleResults("model"), v));
  EXPECT_EQ(v.status, Status::Pass);
  EXPECT_TRUE(v.findings.empty());
  // Nor when the model did not run: its findings are not a diagnosis.
  Results m = modelWithUndefinedRay1();
  m.setStatus(SideStatus::NotSupported, "model lacks it");
  EXPECT_TRUE(judgeUndefinedBehaviour(sampleCase(), sampleResults("vulkan"), m, v));
  EXPECT_TRUE(v.undefined.empty());
}

TEST(UndefinedBehaviourVerdict, ACaseNotClaimingRubIsACaseErrorNamingReasonFieldAndRays) {
  const Case c = sampleCase();  // claims no R-UB
  // Even a device that is wrong on a clear ray is not judged: the case is at fault.
  const Verdict v = compareResults(c, samplePlan(c), deviceWrongOnRay(0), modelWithUndefinedRay1());
  EXPECT_EQ(v.status, Status::CaseError) << allFindings(v);
  EXPECT_TRUE(isFailing(v.status));
  ASSERT_EQ(v.findings.size(), 1u) << allFindings(v);
  const std::string h = v.headline();
  EXPECT_NE(h.find("hit-record-out-of-range"), std::string::npos) << h;
  EXPECT_NE(h.find("pipeline.raygen[0].trace"), std::string::npos) << h;
  EXPECT_NE(h.find("first: 1"), std::string::npos) << h;
  EXPECT_NE(h.find("claim R-UB"), std::string::npos) << h;
  EXPECT_EQ(v.undefined.size(), 1u);
}

TEST(UndefinedBehaviourVerdict, ADeviceCrashOnACaseWithUndefinedBehaviourIsTheCasesError) {
  const Case c = sampleCase();
  for (SideStatus s : {SideStatus::Crash, SideStatus::Timeout}) {
    Results d = sampleResults("vulkan");
    d.setStatus(s, "signal 11");
    const Verdict v = compareResults(c, samplePlan(c), d, modelWithUndefinedRay1());
    EXPECT_EQ(v.status, Status::CaseError) << allFindings(v);
    EXPECT_NE(
        v.headline().find(s == SideStatus::Crash ? "the device crashed" : "the device timed out"),
        std::string::npos)
        << v.headline();
    EXPECT_NE(v.headline().find("the case has undefined behaviour"), std::string::npos)
        << v.headline();
    // Without the model's diagnosis the same crash is the driver's.
    EXPECT_EQ(compareResults(c, samplePlan(c), d, sampleResults("model")).status,
              s == SideStatus::Crash ? Status::Crash : Status::Timeout);
  }
}

TEST(UndefinedBehaviourVerdict, AProbeThatSurvivedPassesAndItsOtherRaysAreJudged) {
  const Case c = probeCase();
  const Verdict v =
      compareResults(c, samplePlan(c), sampleResults("vulkan"), modelWithUndefinedRay1());
  EXPECT_EQ(v.status, Status::Pass) << allFindings(v);
  const Finding* f = findingOf(v, "R-UB");
  ASSERT_TRUE(f);
  EXPECT_EQ(f->status, Status::Pass);
  EXPECT_EQ(f->message.rfind("R-UB probe: ", 0), 0u) << f->message;
  // A clear ray answered wrongly still fails.
  Results d = sampleResults("vulkan");
  setUint(d, 0, "primitive_id", 9);
  EXPECT_EQ(compareResults(c, samplePlan(c), d, modelWithUndefinedRay1()).status, Status::Fail);
}

TEST(UndefinedBehaviourVerdict, AProbeOnWhichTheDeviceCrashedOrHungStaysCrashOrTimeout) {
  const Case c = probeCase();
  for (SideStatus s : {SideStatus::Crash, SideStatus::Timeout}) {
    Results d = sampleResults("vulkan");
    d.setStatus(s, "signal 6");
    const Verdict v = compareResults(c, samplePlan(c), d, modelWithUndefinedRay1());
    EXPECT_EQ(v.status, s == SideStatus::Crash ? Status::Crash : Status::Timeout) << allFindings(v);
    EXPECT_EQ(v.undefined.size(), 1u);
  }
}

}  // namespace
}  // namespace rayspec
