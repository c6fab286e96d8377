// hit_position (origin + t x direction) carries the error of a sphere root's
// t: the model's t bound, scaled by the direction, widens it as it widens
// hit_t (issue 62, judge class 3).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <map>

#include "compare/compare_results.h"
#include "model_support.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

using namespace model_test;

// A unit sphere in a flat box; the ray nearly tangent (its root's t far more
// uncertain than hit_t's own tolerance), its direction 4 long so that the
// position's error is four times t's.
const char* kNearTangentSphere = R"(rules: [R-PREC]
scene:
  blas:
    sphere: [{aabbs: [[-2, -2, -1, 2, 2, 1]], flags: [opaque]}]
  instances: [{blas: sphere}]
rays:
  list:
    - {origin: [0.999, 0, 2], direction: [0, 0, -4]}
    - {origin: [0, 0, 2], direction: [0, 0, -4]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss: [[record: {hit: 0}]]
  hit_groups:
    - intersection:
        - if: sphere_hit
          then: [report: {t: sphere_near, kind: 1}]
      closest_hit: [record: [hit, hit_t, hit_position]]
outputs:
  per_ray: [hit, hit_t, hit_position]
)";

float bound(const std::vector<TBound>& bounds, uint32_t ray) {
  for (const TBound& b : bounds)
    if (b.ray == ray) return b.bound;
  return 0;
}

float readFloat(const Results& r, uint32_t ray, const char* field, uint32_t k = 0) {
  return std::bit_cast<float>(r.records[ray * recordWords() + findRecordField(field)->offset + k]);
}

void writeFloat(Results& r, uint32_t ray, const char* field, uint32_t k, float v) {
  r.records[ray * recordWords() + findRecordField(field)->offset + k] = std::bit_cast<uint32_t>(v);
}

// The model's own results as a device that rounded ray 0's root by `dt`,
// the position moved along the direction by `dp` (dt x 4 when consistent).
Results deviceOff(const Results& model, float dt, float dp) {
  Results d = model;
  d.backend = "vulkan";
  writeFloat(d, 0, "hit_t", 0, readFloat(model, 0, "hit_t") + dt);
  writeFloat(d, 0, "hit_position", 2, readFloat(model, 0, "hit_position", 2) - dp);
  return d;
}

TEST(ModelPositionBound, ASphereRootWithinItsTBoundPassesHitPositionToo) {
  const Case c = parseInline(kNearTangentSphere, "model/position-bound");
  const Plan plan = derivePlan(c);
  const Results m = runTier(c, ModelTier::Exact);
  ASSERT_EQ(m.statusText(), "ok");
  const float tb = bound(m.t_bounds, 0);
  ASSERT_GT(tb, 3e-5f) << "a near-tangent root needs more than hit_t's tolerance (1e-5 + 1e-5 t)";
  EXPECT_FLOAT_EQ(bound(m.position_bounds, 0), 4 * tb) << "t's bound times the direction";
  EXPECT_EQ(bound(m.position_bounds, 1), 0.0f) << "a central root needs no wider position";

  // A device whose root is off by 0.9 of the bound, its position consistent.
  const float dt = 0.9f * tb;
  EXPECT_EQ(compareResults(c, plan, deviceOff(m, dt, 4 * dt), m).status, Status::Pass);
  // Judged as before (no position bound): hit_t passes, hit_position fails.
  Results unbounded = m;
  unbounded.position_bounds.clear();
  const Verdict before = compareResults(c, plan, deviceOff(m, dt, 4 * dt), unbounded);
  EXPECT_EQ(before.status, Status::Fail);
  EXPECT_NE(before.headline().find("hit_position"), std::string::npos) << before.headline();
  EXPECT_EQ(before.headline().find("'hit_t'"), std::string::npos) << before.headline();
  // A position off by more than the propagated bound still fails.
  const Verdict beyond = compareResults(c, plan, deviceOff(m, dt, 1.2f * 4 * tb), m);
  EXPECT_EQ(beyond.status, Status::Fail);
  EXPECT_NE(beyond.headline().find("hit_position"), std::string::npos) << beyond.headline();
}

}  // namespace
}  // namespace rayspec
