#include <gtest/gtest.h>
#include <bit>

#include <cmath>

#include "compare/compare_results.h"
#include "compare/counter_modes.h"
#include "compare/image_pair.h"
#include "compare/shared_edge.h"
#include "compare_samples.h"
#include "program/builtins.h"
#include "results/record_layout.h"
#include "results/tolerances.h"

namespace rayspec {
namespace {

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

// A Fail in several fields names each with its ray count, not only the first.
TEST(Verdict, TheHeadlineNamesEveryFindingOfItsStatus) {
  Verdict v;
  v.add({Status::Fail, "R-BUILTIN", "per-ray field 'instance_id' differs", {0, 1}, 2});
  v.add({Status::QualityWarning, "R-WATERTIGHT", "a leak", {5}, 1});
  v.add({Status::Fail, "R-BUILTIN", "per-ray field 'hit_kind' differs", {1}, 1});
  const std::string h = v.headline();
  EXPECT_EQ(h.rfind("Fail: R-BUILTIN: per-ray field 'instance_id' differs (2 rays; first: 0 1)", 0),
            0u)
      << h;
  EXPECT_NE(h.find("also R-BUILTIN: per-ray field 'hit_kind' differs (1 rays)"), std::string::npos)
      << h;
  EXPECT_EQ(h.find("leak"), std::string::npos) << "a finding of another status: " << h;
  for (int i = 0; i < 10; ++i) v.add({Status::Fail, "R-X", "field " + std::to_string(i), {}, 3});
  EXPECT_NE(v.headline().find("; and 5 more"), std::string::npos) << v.headline();
}

TEST(Compare, IdenticalResultsPass) {
  const Case c = sampleCase();
  const Verdict v =
      compareResults(c, samplePlan(c), sampleResults("vulkan"), sampleResults("model"));
  EXPECT_EQ(v.status, Status::Pass) << v.headline();
}

TEST(Compare, InformationalCounterMayDiffer) {
  const Case c = sampleCase();
  Results d = sampleResults("vulkan");
  setUint(d, 0, "any_hit_runs", 3);
  countFromRecords(d);  // ahit 4, the model's 2
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

// A case that keeps only counters (plan.records off, as builtins/launch-wide):
// its counters are judged against the model's alone, with no records to
// agree with, and still fail when they differ.
TEST(Compare, CountersWithoutRecordsAreJudgedAgainstTheModelAlone) {
  const Case c = sampleCase();
  Results d = sampleResults("vulkan"), m = sampleResults("model");
  d.records.clear();
  m.records.clear();
  EXPECT_EQ(compareResults(c, samplePlan(c), d, m).status, Status::Pass);
  d.counters["miss"] += 1;
  const Verdict v = compareResults(c, samplePlan(c), d, m);
  EXPECT_EQ(v.status, Status::Fail);
  EXPECT_TRUE(findingNames(v, Status::Fail, "counter 'miss' (exact)")) << v.headline();
  EXPECT_FALSE(findingNames(v, Status::Fail, "the records disagree")) << v.headline();
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

TEST(Compare, ModelTBoundWidensTheTToleranceOfThatRayOnly) {
  const Case c = sampleCase();
  Results m = sampleResults("model");
  m.t_bounds.push_back({0, 2e-3f});  // ray 0's t is a sphere root near tangency
  Results d = sampleResults("vulkan");
  setFloat(d, 0, "hit_t", 2.0f + 1e-3f);
  EXPECT_EQ(compareResults(c, samplePlan(c), d, m).status, Status::Pass);
  setFloat(d, 0, "hit_t", 2.0f + 3e-3f);
  EXPECT_EQ(compareResults(c, samplePlan(c), d, m).status, Status::Fail) << "beyond the bound";
  Results other = sampleResults("vulkan");
  setFloat(other, 1, "hit_t", 2.0f + 1e-3f);
  EXPECT_EQ(compareResults(c, samplePlan(c), other, m).status, Status::Fail)
      << "ray 1 has no wider bound";
}

// fuzz/seed-120491 on NVIDIA 580 (ray 13): closest-hit records
// color2 = vec4(hit_position, hit_t) on a ray whose t the model bounds to
// 0.017; the device's t lay 3e-4 from the model's, past the colour
// tolerance. The colour holds what the model knows only to the ray's bound.
Case caseRecordingTInAColour() {
  Case c = sampleCase();
  Expr colour;
  colour.kind = Expr::Kind::Op;
  colour.op = Op::Vec4;
  for (const char* b : {"hit_position", "hit_position", "hit_position", "hit_t"})
    colour.args.push_back(builtinExpr(b));
  Stmt rec;
  rec.kind = Stmt::Kind::Record;
  rec.assigns = {{"color2", colour}, {"hit_t", builtinExpr("hit_t")}};
  c.pipeline.hit_groups[0].closest_hit->push_back(rec);
  c.outputs.per_ray.push_back("color2");
  return c;
}

void setColour2(Results& r, uint32_t ray, float x, float w) {
  const RecordField* f = findRecordField("color2");
  uint32_t* rec = &r.records[ray * recordWords()];
  for (uint32_t k = 0; k < 4; ++k) rec[f->offset + k] = std::bit_cast<uint32_t>(k == 3 ? w : x);
  markWritten(rec, f->index);
}

TEST(Compare, ModelTBoundWidensAColourThatCarriesHitT) {
  const Case c = caseRecordingTInAColour();
  Results m = sampleResults("model"), d = sampleResults("vulkan");
  m.t_bounds.push_back({0, 2e-2f});
  m.position_bounds.push_back({0, 1e-2f});
  for (uint32_t ray : {0u, 1u}) {
    setColour2(m, ray, -2.0673695f, 1.9999652f);
    setColour2(d, ray, -2.0673695f, 1.9999652f);
  }
  setColour2(d, 0, -2.0674081f, 2.0012f);  // within ray 0's bound, past the colour tolerance
  EXPECT_EQ(compareResults(c, samplePlan(c), d, m).status, Status::Pass);
  setColour2(d, 0, -2.0674081f, 2.05f);
  EXPECT_EQ(compareResults(c, samplePlan(c), d, m).status, Status::Fail) << "beyond the bound";
  Results other = d;
  setColour2(other, 0, -2.0673695f, 1.9999652f);
  setColour2(other, 1, -2.0674081f, 2.0012f);
  EXPECT_EQ(compareResults(c, samplePlan(c), other, m).status, Status::Fail)
      << "ray 1 has no wider bound";
  Case exact = c;  // a colour of no bounded built-in keeps the colour tolerance
  for (Expr& a : exact.pipeline.hit_groups[0].closest_hit->back().assigns[0].second.args)
    a = builtinExpr("ray_tmin");
  setColour2(d, 0, -2.0674081f, 2.0012f);
  EXPECT_EQ(compareResults(exact, samplePlan(exact), d, m).status, Status::Fail);
}

TEST(Compare, MissAndClosestHitRunTogetherFails) {
  const Case c = sampleCase();
  Results d = sampleResults("vulkan");
  setUint(d, 2, "closest_hit_runs", 1);
  countFromRecords(d);
  const Verdict v = compareResults(c, samplePlan(c), d, sampleResults("model"));
  EXPECT_EQ(v.status, Status::Fail);
  EXPECT_TRUE(findingNames(v, Status::Fail, "R-MISS-XOR-CHIT")) << v.headline();
}

TEST(Compare, AmbiguousRayLeakIsAQualityWarningAndOtherCandidateIsFine) {
  const Case c = sampleCase();
  Results m = sampleResults("model");
  m.ambiguous.push_back({0, AmbiguityReason::Edge, {{true, 0, 0, 0}, {true, 0, 0, 1}}});
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

// Under SkipClosestHit a hit runs neither closest-hit nor miss: on an
// ambiguous ray that is a hit of unknown identity, legal when a hit is.
TEST(Compare, AnAmbiguousRayWithNeitherClosestHitNorMissIsAHit) {
  const Case c = sampleCase();
  Results m = sampleResults("model");
  m.ambiguous.push_back({0, AmbiguityReason::FirstHit, {{true, 0, 0, 0}, {true, 0, 0, 1}}});
  Results d = sampleResults("vulkan");
  uint32_t* rec = &d.records[0];
  std::fill(rec, rec + kWrittenMaskWords, 0u);  // closest-hit wrote nothing
  setUint(d, 0, "closest_hit_runs", 0);
  countFromRecords(d);
  const Verdict neither = compareResults(c, samplePlan(c), d, m);
  EXPECT_EQ(neither.status, Status::Pass) << neither.headline();
  // A miss there is no legal answer: it breaks R-TOFH.
  setUint(d, 0, "miss_runs", 1);
  countFromRecords(d);
  const Verdict v = compareResults(c, samplePlan(c), d, m);
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
  EXPECT_TRUE(findingNames(v, Status::Fail, "R-TOFH")) << v.headline();
}

// Two triangles sharing the edge x = y of the unit square, in instance 0.
Case squareCase() {
  Case c = sampleCase();
  Geometry g;
  g.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  g.indices = {0, 1, 2, 0, 2, 3};
  c.scene.blases.push_back({"square", {g}, {}});
  Instance in;
  in.blas = 0;
  c.scene.instances.push_back(in);
  return c;
}

TEST(Compare, DoubleHitAtASharedEdgeIsAQualityWarning) {
  // The square's two triangles share the diagonal; any-hit ignores every
  // candidate; ray 2 (a miss in both) crosses the diagonal exactly.
  Case c = squareCase();
  c.scene.blases[0].geometries[0].flags = kGeometryNoDuplicateAnyHit;
  Results model = sampleResults("model");
  setUint(model, 2, "any_hit_runs", 2);  // the model found both triangles once each
  model.ambiguous.push_back(
      {2, AmbiguityReason::Edge, {{false, 0, 0, 0}}, {{true, 0, 0, 0}, {true, 0, 0, 1}}});
  Results once = sampleResults("vulkan");
  setUint(once, 2, "any_hit_runs", 1);  // watertight: one of them
  countFromRecords(once);
  EXPECT_EQ(compareResults(c, samplePlan(c), once, model).status, Status::Pass);
  Results twice = sampleResults("vulkan");
  setUint(twice, 2, "any_hit_runs", 2);  // both: a double hit
  countFromRecords(twice);
  const Verdict v = compareResults(c, samplePlan(c), twice, model);
  EXPECT_EQ(v.status, Status::QualityWarning) << v.headline();
  EXPECT_NE(v.headline().find("double hit"), std::string::npos);
}

// NVIDIA fuzz seeds 120111, 120380 and 120598 (issue 63): the model decided
// the shared triangles as hits but ran no any-hit on them (opaque, or their
// hit group has none); a device that ran any-hit no more often, or once on
// another candidate at the same t (another instance), hit no edge twice.
TEST(Compare, NoDoubleHitWhereTheSharedTrianglesRanNoAnyHit) {
  Case c = squareCase();
  c.scene.blases[0].geometries[0].flags = kGeometryNoDuplicateAnyHit;
  Results model = sampleResults("model");
  setUint(model, 2, "any_hit_runs", 0);
  model.ambiguous.push_back(
      {2, AmbiguityReason::Edge, {{false, 0, 0, 0}}, {{true, 0, 0, 0}, {true, 0, 0, 1}}});
  for (uint32_t runs : {0u, 1u}) {
    Results d = sampleResults("vulkan");
    setUint(d, 2, "any_hit_runs", runs);
    countFromRecords(d);
    const Verdict v = compareResults(c, samplePlan(c), d, model);
    EXPECT_EQ(v.status, Status::Pass) << runs << ": " << v.headline();
  }
}

TEST(Compare, MissAtASharedEdgeIsALeakEvenWhenAMissIsLegal) {
  const Case c = squareCase();
  Results leak = sampleResults("vulkan");
  setUint(leak, 0, "hit", 0);
  setUint(leak, 0, "closest_hit_runs", 0);
  setUint(leak, 0, "miss_runs", 1);
  setUint(leak, 0, "any_hit_runs", 0);  // the device saw no candidate at all
  countFromRecords(leak);
  // The ray crosses the diagonal both triangles share: a miss is a leak.
  Results shared = sampleResults("model");
  shared.ambiguous.push_back(
      {0, AmbiguityReason::Edge, {{true, 0, 0, 0}, {true, 0, 0, 1}, {false, 0, 0, 0}}});
  EXPECT_EQ(compareResults(c, samplePlan(c), leak, shared).status, Status::QualityWarning);
  // The same miss after the device's any-hit saw a candidate (and ignored
  // it, which the legal miss allows) is no leak.
  Results ignored = leak;
  setUint(ignored, 0, "any_hit_runs", 1);
  countFromRecords(ignored);
  EXPECT_EQ(compareResults(c, samplePlan(c), ignored, shared).status, Status::Pass);
  // Corner (0, 0) is in both triangles, but its fan is open (the outer
  // border): a miss is fine.
  Results corner = sampleResults("model");
  corner.ambiguous.push_back({0, AmbiguityReason::Vertex, {{true, 0, 0, 0}, {true, 0, 0, 1}}});
  EXPECT_EQ(compareResults(c, samplePlan(c), leak, corner).status, Status::Pass);
  // The outer border edge (one triangle): hit or miss are both fine, even
  // when the model lists no miss.
  Results border = sampleResults("model");
  border.ambiguous.push_back({0, AmbiguityReason::Edge, {{true, 0, 0, 0}}});
  EXPECT_EQ(compareResults(c, samplePlan(c), leak, border).status, Status::Pass);
  // A miss no rule allows (the model lists a primitive of no triangle) is a leak.
  Results other = sampleResults("model");
  other.ambiguous.push_back({0, AmbiguityReason::Edge, {{true, 0, 0, 7}}});
  EXPECT_EQ(compareResults(c, samplePlan(c), leak, other).status, Status::QualityWarning);
}

TEST(SharedEdge, ClosedFanAroundAVertex) {
  // Four triangles around the centre (0, 0) of a square: closed.
  Case c = sampleCase();
  Geometry g;
  g.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  g.indices = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1};
  c.scene.blases.push_back({"fan", {g}, {}});
  Instance in;
  in.blas = 0;
  c.scene.instances.push_back(in);
  RayAmbiguity a{0,
                 AmbiguityReason::Vertex,
                 {{true, 0, 0, 0}, {true, 0, 0, 1}, {true, 0, 0, 2}, {true, 0, 0, 3}}};
  EXPECT_TRUE(crossesSharedEdge(c, a));
  a.candidates.pop_back();  // three of four: the fan is open
  EXPECT_FALSE(crossesSharedEdge(c, a));
}

// R-AHIT-DUP: under NO_DUPLICATE_ANY_HIT, a ray on which the model committed
// no hit bounds the device's any-hit runs.
TEST(Compare, AnyHitRunsAtMostOncePerPrimitiveUnderNoDuplicate) {
  Case c = sampleCase();
  Geometry g;
  g.flags = kGeometryNoDuplicateAnyHit;
  c.scene.blases.push_back({});
  c.scene.blases[0].geometries.push_back(g);
  Results m = sampleResults("model");
  setUint(m, 2, "any_hit_runs", 2);  // ray 2 missed after any-hit ran on 2 primitives
  Results d = sampleResults("vulkan");
  setUint(d, 2, "any_hit_runs", 2);
  countFromRecords(d);
  EXPECT_EQ(compareResults(c, samplePlan(c), d, m).status, Status::Pass);
  // Fewer is not this rule's business, but R-AHIT-CLOSEST's: both ignored
  // candidates had to be shown to any-hit.
  setUint(d, 2, "any_hit_runs", 1);
  countFromRecords(d);
  const Verdict fewer = compareResults(c, samplePlan(c), d, m);
  EXPECT_FALSE(findingNames(fewer, Status::Fail, "R-AHIT-DUP")) << fewer.headline();
  EXPECT_TRUE(findingNames(fewer, Status::Fail, "R-AHIT-CLOSEST")) << fewer.headline();
  setUint(d, 2, "any_hit_runs", 3);
  countFromRecords(d);
  Verdict v = compareResults(c, samplePlan(c), d, m);
  EXPECT_EQ(v.status, Status::Fail);
  EXPECT_NE(v.headline().find("R-AHIT-DUP"), std::string::npos) << v.headline();
  // Without the flag, duplicates are allowed.
  c.scene.blases[0].geometries[0].flags = 0;
  EXPECT_EQ(compareResults(c, samplePlan(c), d, m).status, Status::Pass);
}

TEST(CompareImages, FloatImagesWithinTheFieldToleranceAndAmbiguousPixelsExcluded) {
  auto image = [](std::vector<float> v) {
    Image im{"t", "hit_t", 2, 2, 1, true, {}};
    for (float f : v) im.texels.push_back(std::bit_cast<uint32_t>(f));
    return im;
  };
  const Image model = image({1.0f, 2.0f, NAN, 4.0f});
  // 2.0 + 1e-6 is within hit_t's tolerance; NaN against NaN is equal.
  EXPECT_EQ(
      countFailingPixels(prepareImagePair(image({1.0f, 2.000001f, NAN, 4.0f}), model, {})).failing,
      0u);
  const Image far = image({1.5f, 2.0f, 0.0f, 4.0f});
  const PixelCount n = countFailingPixels(prepareImagePair(far, model, {}));
  EXPECT_EQ(n.failing, 2u);
  EXPECT_EQ(n.first, (std::vector<uint32_t>{0, 2}));
#ifdef RAYSPEC_WITH_OIIO
  EXPECT_TRUE(n.by_oiio);
#endif
  EXPECT_EQ(countFailingPixelsLoop(prepareImagePair(far, model, {})).failing, 2u)
      << "both counts agree";
  EXPECT_EQ(countFailingPixels(prepareImagePair(far, model, {0, 2})).failing, 0u)
      << "ambiguous pixels excluded";
  // A larger per-image threshold accepts the 0.5 difference (but not NaN against a number).
  EXPECT_EQ(countFailingPixels(prepareImagePair(far, model, {}, 1e5)).failing, 1u);
}

TEST(CompareImages, UintImagesCompareExactly) {
  const Image model{"p", "primitive_id", 3, 1, 1, false, {1, 16777217, 5}};
  const Image device{"p", "primitive_id", 3, 1, 1, false, {1, 16777216, 5}};
  EXPECT_EQ(countFailingPixels(prepareImagePair(device, model, {})).failing, 1u)
      << "ids that round to the same float still differ";
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
  d.setStatus(SideStatus::NotSupported, "no ray tracing");
  EXPECT_EQ(compareResults(c, samplePlan(c), d, sampleResults("model")).status,
            Status::NotSupported);
  d.setStatus(SideStatus::Crash, "VK_ERROR_DEVICE_LOST");
  EXPECT_EQ(compareResults(c, samplePlan(c), d, sampleResults("model")).status, Status::Crash);
  Results m = sampleResults("model");
  m.setStatus(SideStatus::NotSupported, "model lacks it");
  EXPECT_EQ(compareResults(c, samplePlan(c), sampleResults("vulkan"), m).status,
            Status::NotSupported)
      << "no reference is never a pass";
}

TEST(Status, NamesAreStableAndParse) {
  for (Status s : {Status::Pass, Status::Fail, Status::QualityWarning, Status::NotSupported,
                   Status::Crash, Status::Timeout}) {
    Status back;
    ASSERT_TRUE(parseStatus(statusName(s), &back));
    EXPECT_EQ(back, s);
  }
  EXPECT_EQ(worse(Status::Pass, Status::QualityWarning), Status::QualityWarning);
  EXPECT_EQ(worse(Status::Fail, Status::QualityWarning), Status::Fail);
}

}  // namespace
}  // namespace rayspec

namespace rayspec {
namespace {

TEST(CounterModes, DeclaredModesWinAndBoundTheDevice) {
  Case c = sampleCase();
  c.outputs.counter_modes = {{"ahit", "at_least"}};
  EXPECT_EQ(counterModes(c).at("ahit"), CounterMode::AtLeast);
  Results fewer = sampleResults("vulkan");
  setUint(fewer, 0, "any_hit_runs", 0);  // the model ran it twice: the device must too
  countFromRecords(fewer);
  EXPECT_EQ(compareResults(c, samplePlan(c), fewer, sampleResults("model")).status, Status::Fail);
  Results more = sampleResults("vulkan");
  setUint(more, 0, "any_hit_runs", 4);
  countFromRecords(more);
  EXPECT_EQ(compareResults(c, samplePlan(c), more, sampleResults("model")).status, Status::Pass);
  c.outputs.counter_modes = {{"ahit", "at_most"}};
  EXPECT_EQ(compareResults(c, samplePlan(c), more, sampleResults("model")).status, Status::Fail);
  EXPECT_EQ(compareResults(c, samplePlan(c), fewer, sampleResults("model")).status, Status::Pass);
}

}  // namespace
}  // namespace rayspec

namespace rayspec {
namespace {

TEST(CompareImages, CaseThresholdsAllowFailingPixelsAndScaleTheTolerance) {
  const Case c = sampleCase();
  Plan plan = samplePlan(c);
  Results d = sampleResults("vulkan");
  d.images[0].texels[3] = 4;  // one pixel differs (an id image: exactly)
  EXPECT_EQ(compareResults(c, plan, d, sampleResults("model")).status, Status::Fail);
  ImageOutput out{"primitive", "primitive_id", {}};
  out.max_failing_pixels = 1;
  plan.images = {out};
  EXPECT_EQ(compareResults(c, plan, d, sampleResults("model")).status, Status::Pass);
  d.images[0].texels[2] = 4;  // a second one: beyond what the case allows
  EXPECT_EQ(compareResults(c, plan, d, sampleResults("model")).status, Status::Fail);

  // A float image: 3e-4 off is beyond the colour tolerance (1e-4), within 4x it.
  Results fd = sampleResults("vulkan"), fm = sampleResults("model");
  Image color{
      "color", "color", 4, 1, 1, true, {0x3f800000u, 0x3f800000u, 0x3f800000u, 0x3f800000u}};
  fm.images.push_back(color);
  color.texels[1] = std::bit_cast<uint32_t>(1.0f + 3e-4f);
  fd.images.push_back(color);
  ImageOutput strict{"color", "color", {}};
  plan.images = {out, strict};
  EXPECT_EQ(compareResults(c, plan, fd, fm).status, Status::Fail);
  plan.images[1].tolerance = 4.0;
  EXPECT_EQ(compareResults(c, plan, fd, fm).status, Status::Pass);
}

}  // namespace
}  // namespace rayspec
