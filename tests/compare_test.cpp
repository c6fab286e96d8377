#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "compare/compare_results.h"
#include "compare/counter_modes.h"
#include "compare/tolerances.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

Stmt count(const std::string& name) {
  Stmt s;
  s.kind = Stmt::Kind::Count;
  s.counter = name;
  return s;
}

// A case with a miss, a closest-hit and an any-hit counter; 4 rays.
Case sampleCase() {
  Case c;
  c.pipeline.miss.push_back({count("miss")});
  HitGroup g;
  g.closest_hit = Program{count("chit")};
  g.any_hit = Program{count("ahit")};
  c.pipeline.hit_groups.push_back(g);
  c.outputs.counters = {"miss", "chit", "ahit"};
  c.outputs.per_ray = {"hit", "primitive_id", "hit_t"};
  return c;
}

Plan samplePlan(const Case& c) {
  Plan p;
  p.counters = c.outputs.counters;
  p.record_fields = c.outputs.per_ray;
  p.records = true;
  return p;
}

void setUint(Results& r, uint32_t ray, const char* field, uint32_t v) {
  const RecordField* f = findRecordField(field);
  uint32_t* rec = &r.records[ray * recordWords()];
  rec[f->offset] = v;
  if (!f->automatic) rec[kRecordWrittenMaskWord] |= 1u << recordFieldIndex(field);
}

void setFloat(Results& r, uint32_t ray, const char* field, float v) {
  uint32_t w;
  std::memcpy(&w, &v, 4);
  setUint(r, ray, field, w);
}

// Rays 0,1 hit primitives 0,1 at t=2; rays 2,3 miss.
Results sampleResults(const std::string& backend) {
  Results r;
  r.backend = backend;
  r.status = "ok";
  r.width = 4;
  r.height = 1;
  r.records.assign(4 * recordWords(), 0);
  for (uint32_t i = 0; i < 4; ++i) {
    setUint(r, i, "raygen_runs", 1);
    if (i < 2) {
      setUint(r, i, "hit", 1);
      setUint(r, i, "primitive_id", i);
      setFloat(r, i, "hit_t", 2.0f);
      setUint(r, i, "closest_hit_runs", 1);
      setUint(r, i, "any_hit_runs", 1);
    } else {
      setUint(r, i, "hit", 0);
      setUint(r, i, "miss_runs", 1);
    }
  }
  r.counters = {{"miss", 2}, {"chit", 2}, {"ahit", 2}};
  r.images.push_back({"primitive", "primitive_id", 4, 1, 1, false, {0, 1, 0, 0}});
  return r;
}

TEST(CounterModes, TraversalDependentStagesAreInformational) {
  const auto modes = counterModes(sampleCase());
  EXPECT_EQ(modes.at("miss"), CounterMode::Exact);
  EXPECT_EQ(modes.at("chit"), CounterMode::Exact);
  EXPECT_EQ(modes.at("ahit"), CounterMode::Informational);
}

TEST(Tolerances, DocumentedBounds) {
  EXPECT_TRUE(toleranceFor("hit_t").matches(2.0f, 2.0f + 1e-5f));
  EXPECT_FALSE(toleranceFor("hit_t").matches(2.0f, 2.001f));
  EXPECT_FALSE(toleranceFor("hit_t").matches(NAN, 2.0f));
  EXPECT_TRUE(toleranceFor("hit_t").matches(NAN, NAN));
}

TEST(Compare, IdenticalResultsPass) {
  const Case c = sampleCase();
  const Verdict v = compareResults(c, samplePlan(c), sampleResults("vulkan"), sampleResults("model"));
  EXPECT_EQ(v.status, Status::Pass) << v.headline();
}

TEST(Compare, InformationalCounterMayDiffer) {
  const Case c = sampleCase();
  Results d = sampleResults("vulkan");
  d.counters["ahit"] = 7;
  setUint(d, 0, "any_hit_runs", 3);
  EXPECT_EQ(compareResults(c, samplePlan(c), d, sampleResults("model")).status, Status::Pass);
}

TEST(Compare, ExactCounterMismatchFails) {
  const Case c = sampleCase();
  Results d = sampleResults("vulkan");
  d.counters["miss"] = 3;
  const Verdict v = compareResults(c, samplePlan(c), d, sampleResults("model"));
  EXPECT_EQ(v.status, Status::Fail);
  EXPECT_NE(v.headline().find("miss"), std::string::npos);
}

TEST(Compare, ClearRayFieldMismatchNamesRuleAndRay) {
  const Case c = sampleCase();
  Results d = sampleResults("vulkan");
  setUint(d, 1, "primitive_id", 5);
  const Verdict v = compareResults(c, samplePlan(c), d, sampleResults("model"));
  EXPECT_EQ(v.status, Status::Fail);
  EXPECT_NE(v.headline().find("primitive_id"), std::string::npos);
  EXPECT_NE(v.headline().find("first: 1"), std::string::npos) << v.headline();
}

TEST(Compare, TShiftBeyondToleranceFails) {
  const Case c = sampleCase();
  Results d = sampleResults("vulkan");
  setFloat(d, 0, "hit_t", 2.0f + 1e-3f);
  EXPECT_EQ(compareResults(c, samplePlan(c), d, sampleResults("model")).status, Status::Fail);
}

TEST(Compare, MissAndClosestHitRunTogetherFails) {
  const Case c = sampleCase();
  Results d = sampleResults("vulkan");
  setUint(d, 2, "closest_hit_runs", 1);
  const Verdict v = compareResults(c, samplePlan(c), d, sampleResults("model"));
  EXPECT_EQ(v.status, Status::Fail);
  EXPECT_NE(v.headline().find("R-MISS-XOR-CHIT"), std::string::npos);
}

TEST(Compare, AmbiguousRayLeakIsAQualityWarningAndOtherCandidateIsFine) {
  const Case c = sampleCase();
  Results m = sampleResults("model");
  m.ambiguous.push_back({0, "edge", {{true, 0, 0, 0}, {true, 0, 0, 1}}});
  Results d = sampleResults("vulkan");
  setUint(d, 0, "primitive_id", 1);  // the other triangle of the edge: legal
  d.images[0].texels[0] = 1;
  EXPECT_EQ(compareResults(c, samplePlan(c), d, m).status, Status::Pass);
  // Leak: the device missed although a miss is not a legal answer.
  Results leak = sampleResults("vulkan");
  setUint(leak, 0, "hit", 0);
  setUint(leak, 0, "closest_hit_runs", 0);
  setUint(leak, 0, "miss_runs", 1);
  leak.counters["miss"] = 3;
  leak.counters["chit"] = 1;
  const Verdict v = compareResults(c, samplePlan(c), leak, m);
  EXPECT_EQ(v.status, Status::QualityWarning) << v.headline();
  // A primitive outside the candidates is a hard failure.
  Results wrong = sampleResults("vulkan");
  setUint(wrong, 0, "primitive_id", 9);
  EXPECT_EQ(compareResults(c, samplePlan(c), wrong, m).status, Status::Fail);
}

TEST(Compare, ImageMismatchFails) {
  const Case c = sampleCase();
  Results d = sampleResults("vulkan");
  d.images[0].texels[3] = 4;
  const Verdict v = compareResults(c, samplePlan(c), d, sampleResults("model"));
  EXPECT_EQ(v.status, Status::Fail);
  EXPECT_NE(v.headline().find("image"), std::string::npos);
}

TEST(Compare, ValidationErrorFails) {
  const Case c = sampleCase();
  Results d = sampleResults("vulkan");
  d.validation_messages.push_back("VUID-something");
  EXPECT_EQ(compareResults(c, samplePlan(c), d, sampleResults("model")).status, Status::Fail);
}

TEST(Compare, BackendStatusesMapToVerdicts) {
  const Case c = sampleCase();
  Results d = sampleResults("vulkan");
  d.status = "NotSupported: no ray tracing";
  EXPECT_EQ(compareResults(c, samplePlan(c), d, sampleResults("model")).status, Status::NotSupported);
  d.status = "Crash: VK_ERROR_DEVICE_LOST";
  EXPECT_EQ(compareResults(c, samplePlan(c), d, sampleResults("model")).status, Status::Crash);
  Results m = sampleResults("model");
  m.status = "NotSupported: model lacks it";
  EXPECT_EQ(compareResults(c, samplePlan(c), sampleResults("vulkan"), m).status, Status::NotSupported)
      << "no reference is never a pass";
}

TEST(Status, NamesAreStableAndParse) {
  for (Status s : {Status::Pass, Status::Fail, Status::QualityWarning, Status::NotSupported, Status::Crash,
                   Status::Timeout}) {
    Status back;
    ASSERT_TRUE(parseStatus(statusName(s), &back));
    EXPECT_EQ(back, s);
  }
  EXPECT_EQ(worse(Status::Pass, Status::QualityWarning), Status::QualityWarning);
  EXPECT_EQ(worse(Status::Fail, Status::QualityWarning), Status::Fail);
}

}  // namespace
}  // namespace rayspec
