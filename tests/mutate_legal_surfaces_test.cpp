// A ray numerically ambiguous at two surfaces in a row (issue 63): a
// plate's border edge in front, which a device may hit or pass, and a
// floor's shared edge behind, which either of its triangles may take. Every
// combination is legal, a device passing the plate and taking the floor
// triangle the model does not take among them; the judge still fails an
// answer that is none of them. A shared edge in front, passed between (a
// leak, R-WATERTIGHT's "should"), then either triangle of a shared edge
// behind: each a QualityWarning, and one where only a value tells the leak
// (accel/sparse). And a ray through a border vertex of a non-opaque mesh
// may meet no triangle there (its any-hit not run).
#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>
#include <utility>

#include "compare/compare_results.h"
#include "model_support.h"
#include "mutate/legal_devices.h"

namespace rayspec {
namespace {

using model_test::ambiguityOf;
using model_test::diagonalSquareBlas;
using model_test::parseInline;

// A plate of one triangle at z = 0 whose border edge is the diagonal x = y
// (on its upper side or its lower side), and behind it at z = -2 a floor
// square whose two triangles share that diagonal. Ray 0 runs down the
// diagonal at (0.25, 0.25); ray 1 hits the plate clearly.
std::string twoSurfaces(bool upper) {
  const std::string plate =
      upper ? "[[-1, -1, 0], [1, 1, 0], [-1, 1, 0]]" : "[[-1, -1, 0], [1, -1, 0], [1, 1, 0]]";
  const std::string ray1 = upper ? "[-0.5, 0.5, 5]" : "[0.5, -0.5, 5]";
  return R"(rules: [R-WATERTIGHT]
description: a plate's border edge in front of a floor's shared edge
scene:
  blas:
    plate:
      - triangles: {vertices: )" +
         plate + R"(}
    floor:
      - triangles:
          vertices: [[-1, -1, -2], [1, -1, -2], [1, 1, -2], [-1, 1, -2]]
          indices: [0, 1, 2, 0, 2, 3]
  instances: [{blas: plate}, {blas: floor}]
rays:
  list:
    - {origin: [0.25, 0.25, 5], direction: [0, 0, -1]}
    - {origin: )" +
         ray1 + R"(, direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss:
    - [record: {hit: 0}]
  hit_groups:
    - closest_hit: [record: [hit, instance_id, primitive_id, hit_t]]
outputs:
  per_ray: [hit, instance_id, primitive_id, hit_t]
)";
}

struct Answer {
  uint32_t instance, primitive;
  float t;
};

// A device that answers ray 0 with `a` (hit, its instance, primitive and
// t), ray 1 as the model does.
Results deviceAnswering(const Case& c, const Results& model, const Answer& a) {
  Results r = perfectDevice(c, model);
  r.backend = "vulkan";
  uint32_t* rec = &r.records[0];
  rec[findRecordField("hit")->offset] = 1;
  rec[findRecordField("instance_id")->offset] = a.instance;
  rec[findRecordField("primitive_id")->offset] = a.primitive;
  std::memcpy(&rec[findRecordField("hit_t")->offset], &a.t, sizeof(float));
  return r;
}

TEST(TwoSurfaces, EveryCombinationOfTheTwoEdgesIsALegalAnswer) {
  for (bool upper : {true, false}) {
    const Case c = parseInline(twoSurfaces(upper));
    const Plan plan = derivePlan(c);
    const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
    const RayAmbiguity* a = ambiguityOf(model, 0);
    ASSERT_NE(a, nullptr);
    std::set<std::pair<uint32_t, uint32_t>> hits;
    for (const Candidate& k : a->candidates)
      if (k.hit) hits.insert({k.instance, k.primitive});
    EXPECT_EQ(hits, (std::set<std::pair<uint32_t, uint32_t>>{{0, 0}, {1, 0}, {1, 1}}))
        << (upper ? "upper" : "lower") << " plate: the plate and each floor triangle";
    // A device passing the plate takes either floor triangle: each Passes.
    for (const Answer& legal : {Answer{0, 0, 5.0f}, Answer{1, 0, 7.0f}, Answer{1, 1, 7.0f}}) {
      const Verdict v = compareResults(c, plan, deviceAnswering(c, model, legal), model);
      EXPECT_EQ(v.status, Status::Pass)
          << (upper ? "upper" : "lower") << " plate, answer " << legal.instance << "."
          << legal.primitive << ": " << v.headline();
    }
    for (const LegalDevice& d : judgeLegalDevices(c, plan, model, 1))
      EXPECT_FALSE(d.false_alarm) << d.name << ": " << d.headline;
  }
}

TEST(TwoSurfaces, AnAnswerOfNoCombinationStillFails) {
  for (bool upper : {true, false}) {
    const Case c = parseInline(twoSurfaces(upper));
    const Plan plan = derivePlan(c);
    const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
    // The plate at the floor's t, a floor triangle at the plate's: no legal
    // answer writes either.
    for (const Answer& wrong : {Answer{0, 0, 7.0f}, Answer{1, 1, 5.0f}, Answer{1, 2, 7.0f}}) {
      const Verdict v = compareResults(c, plan, deviceAnswering(c, model, wrong), model);
      EXPECT_EQ(v.status, Status::Fail)
          << (upper ? "upper" : "lower") << " plate, answer " << wrong.instance << "."
          << wrong.primitive << ": " << v.headline();
    }
  }
}

// Two squares, each of two triangles sharing the diagonal x = y: one at
// z = 0, the floor at z = -2. Ray 0 runs down the diagonal at (0.25, 0.25)
// (a device may pass between the front square's triangles, then take
// either floor triangle); ray 1 hits the front square clearly.
const char* kLeakThenSharedEdge = R"(rules: [R-WATERTIGHT]
description: a shared edge leaked through in front of a floor's shared edge
scene:
  blas:
    square:
      - triangles:
          vertices: [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
          indices: [0, 1, 2, 0, 2, 3]
    floor:
      - triangles:
          vertices: [[-1, -1, -2], [1, -1, -2], [1, 1, -2], [-1, 1, -2]]
          indices: [0, 1, 2, 0, 2, 3]
  instances: [{blas: square}, {blas: floor}]
rays:
  list:
    - {origin: [0.25, 0.25, 5], direction: [0, 0, -1]}
    - {origin: [0.5, -0.5, 5], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss:
    - [record: {hit: 0}]
  hit_groups:
    - closest_hit: [record: [hit, instance_id, primitive_id, hit_t]]
outputs:
  per_ray: [hit, instance_id, primitive_id, hit_t]
)";

TEST(LeakThenSharedEdge, PassingBetweenThenEitherFloorTriangleIsAQualityWarning) {
  const Case c = parseInline(kLeakThenSharedEdge);
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
  const RayAmbiguity* a = ambiguityOf(model, 0);
  ASSERT_NE(a, nullptr);
  std::set<std::pair<uint32_t, uint32_t>> leaks;
  for (const Candidate& k : a->leak_answers)
    if (k.hit) leaks.insert({k.instance, k.primitive});
  EXPECT_EQ(leaks, (std::set<std::pair<uint32_t, uint32_t>>{{1, 0}, {1, 1}}))
      << "past the front square, each floor triangle";
  // The model's own floor triangle and the other: each passed between.
  for (const Answer& leak : {Answer{1, 0, 7.0f}, Answer{1, 1, 7.0f}}) {
    const Verdict v = compareResults(c, plan, deviceAnswering(c, model, leak), model);
    EXPECT_EQ(v.status, Status::QualityWarning)
        << "floor triangle " << leak.primitive << ": " << v.headline();
  }
  for (const LegalDevice& d : judgeLegalDevices(c, plan, model, 1))
    EXPECT_FALSE(d.false_alarm) << d.name << ": " << d.headline;
}

TEST(LeakThenSharedEdge, AnAnswerOfNoCombinationStillFails) {
  const Case c = parseInline(kLeakThenSharedEdge);
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
  // A floor triangle at the square's t, the square at the floor's, a
  // primitive the floor has not.
  for (const Answer& wrong : {Answer{1, 1, 5.0f}, Answer{0, 1, 7.0f}, Answer{1, 2, 7.0f}}) {
    const Verdict v = compareResults(c, plan, deviceAnswering(c, model, wrong), model);
    EXPECT_EQ(v.status, Status::Fail) << "answer " << wrong.instance << "." << wrong.primitive
                                      << " at " << wrong.t << ": " << v.headline();
  }
}

// accel/sparse's shape: a square of two triangles sharing the diagonal x =
// y, a floor clear behind it, and only a value recorded (the hit's custom
// index * 1000 + primitive; 99999 on a miss): the record names no hit, so
// only the replay of the leak tells a device that passed between (value
// 3000) from one that answers wrongly.
const char* kLeakToAValue = R"(rules: [R-WATERTIGHT]
description: an edge ray with a clear floor behind, only a value recorded
scene:
  blas:
    square:
      - triangles:
          vertices: [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
          indices: [0, 1, 2, 0, 2, 3]
    floor:
      - triangles: {vertices: [[-9, -9, -2], [9, -9, -2], [0, 9, -2]]}
  instances: [{blas: square, custom_index: 1}, {blas: floor, custom_index: 3}]
rays:
  list:
    - {origin: [0.25, 0.25, 5], direction: [0, 0, -1]}
    - {origin: [0.5, -0.5, 5], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  raygen:
    - trace: {}
    - record: {value: payload.value}
  miss:
    - [payload: {value: 99999}]
  hit_groups:
    - closest_hit: [payload: {value: {add: [{mul: [instance_custom_index, 1000]}, primitive_id]}}]
outputs:
  per_ray: [value]
)";

Results deviceValuing(const Case& c, const Results& model, uint32_t value) {
  Results r = perfectDevice(c, model);
  r.backend = "vulkan";
  r.records[findRecordField("value")->offset] = value;
  return r;
}

TEST(LeakToAValue, ARecordOnlyALeakLeavesIsAQualityWarning) {
  const Case c = parseInline(kLeakToAValue);
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
  const RayAmbiguity* a = ambiguityOf(model, 0);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->leak_replays.size(), 1u) << "the floor's value, past the square";
  for (uint32_t legal : {1000u, 1001u})
    EXPECT_EQ(compareResults(c, plan, deviceValuing(c, model, legal), model).status, Status::Pass)
        << legal;
  Verdict v = compareResults(c, plan, deviceValuing(c, model, 3000), model);
  EXPECT_EQ(v.status, Status::QualityWarning) << v.headline();
  for (uint32_t wrong : {3001u, 2000u, 1002u}) {
    v = compareResults(c, plan, deviceValuing(c, model, wrong), model);
    EXPECT_EQ(v.status, Status::Fail) << wrong << ": " << v.headline();
  }
  for (const LegalDevice& d : judgeLegalDevices(c, plan, model, 1))
    EXPECT_FALSE(d.false_alarm) << d.name << ": " << d.headline;
}

// A non-opaque square of two triangles sharing the diagonal from (-1, -1)
// to (1, 1), its any-hit counting and ignoring: rays through its border
// vertices (one triangle's corner, the two triangles' shared corner) and a
// border edge's middle. A device may meet no triangle at each: a miss, no
// any-hit run (the miss records the payload any-hit sets: 7 after it, 0
// without).
const std::string kBorderVertices = R"(rules: [R-WATERTIGHT]
description: rays through a non-opaque mesh's border vertices
scene:
  blas:
)" + diagonalSquareBlas("[]") + R"(  instances: [{blas: square}]
rays:
  list:
    - {origin: [1, -1, 5], direction: [0, 0, -1]}
    - {origin: [1, 1, 5], direction: [0, 0, -1]}
    - {origin: [-1, -1, 5], direction: [0, 0, -1]}
    - {origin: [-1, 1, 5], direction: [0, 0, -1]}
    - {origin: [0, -1, 5], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  raygen:
    - trace: {}
  miss:
    - [count: miss, record: {value: payload.value}]
  hit_groups:
    - any_hit: [count: ahit, payload: {value: 7}, ignore]
      closest_hit: [record: {value: 1}]
outputs:
  counters: [ahit, miss]
  per_ray: [value]
)";

// A device that meets no triangle on any of `rays` rays: each a miss (its
// record and run counts), no any-hit run.
Results missingEverything(const Case& c, const Results& model, uint32_t rays) {
  Results r = perfectDevice(c, model);
  r.backend = "vulkan";
  auto set = [&](uint32_t ray, const char* field, uint32_t value) {
    r.records[ray * recordWords() + findRecordField(field)->offset] = value;
  };
  for (uint32_t ray = 0; ray < rays; ++ray) {
    set(ray, "value", 0);
    set(ray, "any_hit_runs", 0);
    set(ray, "closest_hit_runs", 0);
    set(ray, "miss_runs", 1);
  }
  r.counters.at("ahit") = 0;
  r.counters.at("miss") = rays;
  return r;
}

TEST(BorderVertices, ADeviceMeetingNoTriangleThereRunsNoAnyHit) {
  const Case c = parseInline(kBorderVertices);
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
  EXPECT_EQ(model.ambiguous.size(), 5u) << "every ray meets a border";
  Results device = missingEverything(c, model, 5);  // every ray passes beside the square
  Verdict v = compareResults(c, plan, device, model);
  EXPECT_EQ(v.status, Status::Pass) << v.headline();
  device.counters.at("ahit") = 100;  // more any-hits than any legal answer runs
  v = compareResults(c, plan, device, model);
  EXPECT_EQ(v.status, Status::Fail) << v.headline();
}

// The same square at z = 0, one ray through its corner (x, y), and in
// front at z = 2 an opaque plate whose border edge on the line through x
// the ray runs along (the plate's third corner at plate_x, on either side): the device may hit the
// plate, or pass it and meet the corner's triangle (any-hit run, ignored),
// or pass both (a miss, no any-hit run).
std::string plateInFrontOfCorner(float x, float plate_x, float y) {
  std::string text = kBorderVertices;
  const std::string rays = text.substr(text.find("    - {origin: [1, -1"),
                                       text.find("  tmin:") - text.find("    - {origin: [1, -1"));
  text.replace(text.find(rays), rays.size(),
               "    - {origin: [" + std::to_string(x) + ", " + std::to_string(y) +
                   ", 5], direction: [0, 0, -1]}\n");
  const std::string square = "  instances: [{blas: square}]\n";
  text.replace(
      text.find(square), square.size(),
      "    plate:\n      - triangles: {vertices: [[" + std::to_string(x) + ", -3, 2], [" +
          std::to_string(x) + ", 3, 2], [" + std::to_string(plate_x) +
          ", 0, 2]]}\n        flags: [opaque]\n  instances: [{blas: square}, {blas: plate}]\n");
  return text;
}

TEST(BorderVertices, ADeviceMissingThePlateInFrontAndTheCornerBehindRunsNoAnyHit) {
  for (float x : {-1.0f, 1.0f})
    for (float plate_x : {x - 2, x + 2})
      for (float y : {-1.0f, 1.0f}) {
        const Case c = parseInline(plateInFrontOfCorner(x, plate_x, y));
        const Plan plan = derivePlan(c);
        const Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
        const Verdict v = compareResults(c, plan, missingEverything(c, model, 1), model);
        EXPECT_EQ(v.status, Status::Pass) << "corner " << x << ", " << y << ", plate towards x "
                                          << plate_x << ": " << v.headline();
      }
}

}  // namespace
}  // namespace rayspec
