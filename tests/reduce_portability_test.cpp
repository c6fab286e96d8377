// A reduction step must keep the case portable (reduce/portability_check.h):
// the issue 62 reduction that cut an intersection program's guard
// `{and: [sphere_hit, far >= tmin, near <= tmax]}` down to `far >= tmin`.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "library/case_discovery.h"
#include "mutate/case_portability.h"
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

Case dataCase(const std::string& path) {
  const std::string data = RAYSPEC_SOURCE_DIR "/tests/data/";
  const std::vector<CaseFile> files = caseFilesFor(data + path, data);
  EXPECT_EQ(files.size(), 1u) << path;
  const ParseResult p = files.empty() ? ParseResult{} : loadCase(files.front(), data);
  EXPECT_TRUE(p.value && p.errors.empty()) << path;
  return p.value ? *p.value : Case{};
}

// The check is `rayspec check`'s (mutate/case_portability.h), not one of its
// own: a variant it refuses is refused with the legal device and the finding
// check names (a step from each fixed case of tests/data/portable to its
// mistake in tests/data/not-portable, issue 61).
TEST(ReducePortability, RefusesAsRayspecCheckDoes) {
  for (const char* name : {"box-report", "candidates"}) {
    const std::string fixed =
        std::string(name) == "box-report" ? "box-report-tested.yaml" : "candidates-at-least.yaml";
    const std::string broken =
        std::string(name) == "box-report" ? "box-report-untested.yaml" : "candidates-exact.yaml";
    const Case variant = dataCase("not-portable/" + broken);
    const CasePortability checked = checkPortability(variant, 2);
    ASSERT_FALSE(checked.problems.empty()) << broken;
    // Each refusal check could give: a failing device, and check's finding
    // (once: not the verdict's "Fail: " before it).
    std::set<std::string> refusals;
    for (const NotPortable& p : checked.problems) {
      refusals.insert("not portable: legal device " + p.device + " fails: " + p.finding);
      for (const std::string& also : p.also)
        refusals.insert("not portable: legal device " + also + " fails: " + p.finding);
    }
    const PortabilityCheck check(dataCase("portable/" + fixed), 2);
    EXPECT_EQ(check.whyNotPortable(dataCase("portable/" + fixed)), "") << fixed;
    const std::string why = check.whyNotPortable(variant);
    EXPECT_TRUE(refusals.count(why)) << why << "\ncheck's first: " << *refusals.begin();
    // The reduction's own original is never held against it.
    EXPECT_EQ(PortabilityCheck(variant, 2).whyNotPortable(variant), "") << broken;
  }
}

}  // namespace
}  // namespace rayspec
