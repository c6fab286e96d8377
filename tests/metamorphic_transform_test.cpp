// Rigid motions of a case (metamorphic/transform_case.h), and the stability
// families under motions and permutations: the exact tier's leak and
// double-hit counts (none) and its hits per ray must not move.
#include <gtest/gtest.h>

#include <cstdio>

#include "metamorphic/permute_case.h"
#include "metamorphic/transform_case.h"
#include "model/model_engine.h"
#include "plan/plan.h"
#include "result_support.h"
#include "stability/leak_counts.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

Results exact(const Case& c) {
  return runOnModel(c, derivePlan(c), ModelOptions{ModelTier::Exact, 2});
}

const char* kCase = R"(rules: [R-WATERTIGHT]
scene:
  blas:
    m: [{triangles: {grid: {cells: [2, 2], size: [2, 2]}}}]
  instances: [{blas: m, transform: [1, 0, 0, 3, 0, 1, 0, 0.5, 0, 0, 1, 0]}]
rays:
  list: [{origin: [3.25, 0.5, 2], direction: [0, 0.5, -1]}]
pipeline: {miss: [[]], hit_groups: [{}]}
)";

TEST(MoveCase, MapsInstancesAndRaysExactly) {
  ParseResult p = parseCaseText(kCase, "t.yaml", "family/t");
  ASSERT_TRUE(p.value);
  std::string why;
  // new x = -old y + 1024, new y = old x, new z = old z (a turn by 90 degrees about z).
  const std::optional<Case> m =
      valueOrMessage(moveCase(*p.value, {{1, 0, 2}, {-1, 1, 1}, {1024, 0, 0}}), &why);
  ASSERT_TRUE(m) << why;
  EXPECT_EQ(m->rays.rays[0].origin, (Vec3{1023.5f, 3.25f, 2}));
  EXPECT_EQ(m->rays.rays[0].direction, (Vec3{-0.5f, 0, -1}));
  EXPECT_EQ(m->scene.instances[0].transform,
            (Transform{0, -1, 0, 1023.5f, 1, 0, 0, 3, 0, 0, 1, 0}));
  // Not exact in float: 2^25 + 0.5.
  EXPECT_FALSE(valueOrMessage(moveCase(*p.value, {{0, 1, 2}, {1, 1, 1}, {33554432, 0, 0}}), &why));
  EXPECT_NE(why.find("not exact"), std::string::npos);
  EXPECT_FALSE(valueOrMessage(moveCase(*p.value, {{0, 0, 2}, {1, 1, 1}, {0, 0, 0}}), &why));
  EXPECT_NE(why.find("signed permutation"), std::string::npos);
}

void expectSameCounts(const Case& c, const Results& base, const Results& moved,
                      const std::string& what) {
  ASSERT_EQ(moved.statusText(), "ok") << c.name << " " << what;
  const LeakCounts a = countLeaks(base), b = countLeaks(moved);
  EXPECT_EQ(a.rays, b.rays) << c.name << " " << what;
  EXPECT_EQ(b.leaks, 0u) << c.name << " " << what;
  EXPECT_EQ(b.doubles, 0u) << c.name << " " << what;
  EXPECT_EQ(a.leaks, b.leaks) << c.name << " " << what;
  EXPECT_EQ(a.doubles, b.doubles) << c.name << " " << what;
}

// Every stability case, turned, cycled through its axes and translated,
// mirrored, and permuted: the exact tier hits exactly one triangle on every
// ray, as before.
TEST(MoveCase, StabilityFamiliesKeepTheirCounts) {
  const RigidMotion motions[] = {{{1, 0, 2}, {-1, 1, 1}, {0, 0, 0}},
                                 {{2, 0, 1}, {1, 1, 1}, {1024, -2048, 4096}},
                                 {{0, 1, 2}, {1, 1, -1}, {0, 0, 0}}};
  int cases = 0, moved = 0, refused = 0;
  for (const CaseFile& f : suiteCases()) {
    if (f.name.rfind("stability/", 0) != 0) continue;
    ParseResult parsed = loadSuiteCase(f);
    ASSERT_TRUE(parsed.value) << f.name;
    const Case& c = *parsed.value;
    const Results base = exact(c);
    ASSERT_EQ(base.statusText(), "ok") << c.name;
    ++cases;
    for (const RigidMotion& m : motions) {
      std::string why;
      const std::optional<Case> mc = valueOrMessage(moveCase(c, m), &why);
      if (!mc) {
        ++refused;  // a translation that is not exact at this scale: not this case's check
        continue;
      }
      ++moved;
      expectSameCounts(c, base, exact(*mc), "moved");
    }
    expectSameCounts(c, base, exact(permuteCase(c, 5).permuted), "permuted");
  }
  std::printf("%d stability cases, %d moved, %d motions refused as inexact\n", cases, moved,
              refused);
  EXPECT_GE(cases, 6);
  EXPECT_GT(moved, 2 * cases);
}

}  // namespace
}  // namespace rayspec
