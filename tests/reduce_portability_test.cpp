// A reduction step must keep the case portable (reduce/portability_check.h):
// the issue 62 reduction that cut an intersection program's guard
// `{and: [sphere_hit, far >= tmin, near <= tmax]}` down to `far >= tmin`.
#include <gtest/gtest.h>

#include <string>

#include "parse/parse_case.h"
#include "reduce/portability_check.h"

namespace rayspec {
namespace {

// A sphere in box 0 under the ray; box 1 beside the ray and nearer its
// origin, wide enough that a device may run its program (R-AABB-CONS: the
// AABB test is conservative). GUARD is the intersection program's condition.
const char* kTwoBoxes = R"(rules: [R-AABB-CONS, R-ISECT-CLOSEST]
scene:
  blas:
    two: [{aabbs: [[-1, -1, -1, 1, 1, 1], [1.2, -1, 2, 3.2, 1, 3]], flags: [opaque]}]
  instances: [{blas: two}]
rays:
  list:
    - {origin: [0, 0, 5], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss: [[record: {hit: 0}]]
  hit_groups:
    - intersection:
        - if: GUARD
          then: [report: {t: {max: [sphere_near, ray_tmin]}, kind: 1}]
      closest_hit: [record: [hit, primitive_id, hit_t]]
outputs:
  per_ray: [hit, primitive_id, hit_t]
)";

Case withGuard(const std::string& guard) {
  std::string text = kTwoBoxes;
  text.replace(text.find("GUARD"), 5, guard);
  const ParseResult p = parseCaseText(text, "reduce/portable.yaml", "reduce/portable");
  EXPECT_TRUE(p.value.has_value() && p.errors.empty())
      << (p.errors.empty() ? "" : p.errors[0].format());
  return p.value ? *p.value : Case{};
}

constexpr const char* kWholeGuard =
    "{and: [sphere_hit, {ge: [sphere_far, ray_tmin]}, {le: [sphere_near, ray_tmax]}]}";

TEST(ReducePortability, ADroppedSphereTestIsNotPortable) {
  const PortabilityCheck check(withGuard(kWholeGuard), 2);
  EXPECT_EQ(check.whyNotPortable(withGuard(kWholeGuard)), "") << "the original is portable";
  EXPECT_EQ(check.whyNotPortable(withGuard("sphere_hit")), "")
      << "the sphere test alone still keeps box 1's program from reporting";
  // Without sphere_hit, box 1's program reports t = 2.5 (the ray's nearest
  // approach to its sphere's centre), before box 0's hit at 4, whenever a
  // device runs it.
  const std::string why = check.whyNotPortable(withGuard("{ge: [sphere_far, ray_tmin]}"));
  EXPECT_NE(why.find("not portable: legal device aabb-neighbours fails"), std::string::npos) << why;
}

}  // namespace
}  // namespace rayspec
