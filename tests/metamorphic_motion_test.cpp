// The motion's command-line text (metamorphic/motion_spec.h) and the scope
// `rayspec run --move` moves a case in (MoveScope::Verdict).
#include <gtest/gtest.h>

#include <cmath>

#include "metamorphic/motion_spec.h"
#include "metamorphic/transform_case.h"
#include "parse/parse_case.h"
#include "result_support.h"

namespace rayspec {
namespace {

TEST(MotionSpec, ReadsSignedAxesAndATranslationAndWritesThemBack) {
  std::string why;
  const std::optional<RigidMotion> turn = valueOrMessage(parseMotionSpec("-y,x,z"), &why);
  ASSERT_TRUE(turn) << why;
  EXPECT_EQ(turn->axis, (std::array<int, 3>{1, 0, 2}));
  EXPECT_EQ(turn->sign, (std::array<int, 3>{-1, 1, 1}));
  EXPECT_EQ(turn->translate, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(motionSpecText(*turn), "-y,x,z");
  const std::optional<RigidMotion> moved =
      valueOrMessage(parseMotionSpec("z, -x, +y, 1024, -2048, 0.5"), &why);
  ASSERT_TRUE(moved) << why;
  EXPECT_EQ(moved->translate, (std::array<double, 3>{1024, -2048, 0.5}));
  EXPECT_EQ(motionSpecText(*moved), "z,-x,y,1024,-2048,0.5");
}

TEST(MotionSpec, BadTextSaysWhatIsWrong) {
  std::string why;
  EXPECT_FALSE(valueOrMessage(parseMotionSpec("x,y"), &why));
  EXPECT_NE(why.find("three signed axes"), std::string::npos) << why;
  EXPECT_FALSE(valueOrMessage(parseMotionSpec("x,x,z"), &why));
  EXPECT_NE(why.find("once"), std::string::npos) << why;
  EXPECT_FALSE(valueOrMessage(parseMotionSpec("x,w,z"), &why));
  EXPECT_NE(why.find("'w' (term 2)"), std::string::npos) << why;
  EXPECT_FALSE(valueOrMessage(parseMotionSpec("x,y,z,1,2,nan"), &why));
  EXPECT_NE(why.find("term 6"), std::string::npos) << why;
  EXPECT_FALSE(valueOrMessage(parseMotionSpec("x,y,z,1,2"), &why));
  // A translation term that is no float (the moved sums are float sums).
  EXPECT_FALSE(valueOrMessage(parseMotionSpec("x,y,z,0,0,0.1"), &why));
  EXPECT_NE(why.find("'0.1' (term 6): not a finite number exact in float"), std::string::npos)
      << why;
}

// A raygen that counts before its trace, a closest-hit that branches on a
// world-space built-in; a ray with NaN in its origin (undefined).
const char* kBranching = R"(rules: [R-PAYLOAD, R-UB]
scene:
  blas:
    m: [{triangles: {vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}}]
  instances: [{blas: m}]
rays:
  list: [{origin: [0.25, 0.25, 1], direction: [0, 0, -1]}, {origin: [.nan, 0, 1], direction: [0, 0, -1]}]
pipeline:
  raygen: [count: launched, trace: {}]
  miss: [[]]
  hit_groups:
    - closest_hit:
        - if: {gt: [{x: world_ray_origin}, 0.0]}
          then: [count: east]
outputs: {counters: [launched, east]}
)";

TEST(MoveCase, VerdictScopeMovesCasesThatBranchOrDoMoreThanTrace) {
  ParseResult p = parseCaseText(kBranching, "b.yaml", "family/b");
  ASSERT_TRUE(p.value) << (p.errors.empty() ? "" : p.errors.front().format());
  std::string why;
  const RigidMotion m = *valueOrMessage(parseMotionSpec("-y,x,z,2,-4,8"), &why);
  // The count check's scope refuses it (a branch could change its mind).
  EXPECT_FALSE(valueOrMessage(moveCase(*p.value, m, MoveScope::SameGeometry), &why));
  const std::optional<Case> moved = valueOrMessage(moveCase(*p.value, m, MoveScope::Verdict), &why);
  ASSERT_TRUE(moved) << why;
  EXPECT_EQ(moved->rays.rays[0].origin, (Vec3{1.75f, -3.75f, 9}));
  EXPECT_TRUE(std::isnan(moved->rays.rays[1].origin[1]));  // an undefined ray stays undefined
  EXPECT_NE(moved->source_hash,
            p.value->source_hash);  // a saved bundle of the unmoved case does not match
  const std::optional<Case> again = valueOrMessage(moveCase(*p.value, m, MoveScope::Verdict), &why);
  EXPECT_EQ(again->source_hash, moved->source_hash);
}

TEST(MoveCase, ATraceWithItsOwnOriginOrDirectionIsNotMoved) {
  std::string text = kBranching;
  const std::string from = "trace: {}]";
  text.replace(text.find(from), from.size(), "trace: {direction: [0.0, 0.0, -1.0]}]");
  ParseResult p = parseCaseText(text, "b.yaml", "family/b");
  ASSERT_TRUE(p.value) << (p.errors.empty() ? "" : p.errors.front().format());
  std::string why;
  EXPECT_FALSE(valueOrMessage(
      moveCase(*p.value, *valueOrMessage(parseMotionSpec("x,y,-z"), &why), MoveScope::Verdict),
      &why));
  EXPECT_NE(why.find("its own origin or direction"), std::string::npos) << why;
}

// A translation of 2^60 (a float) added to an origin of 0.25: the sum rounds in
// double as well as in float, so the case is not moved (it was, and the moved
// ray missed where the unmoved one hit).
TEST(MoveCase, ASumThatRoundsInDoubleIsNotExact) {
  ParseResult p = parseCaseText(kBranching, "b.yaml", "family/b");
  ASSERT_TRUE(p.value) << (p.errors.empty() ? "" : p.errors.front().format());
  std::string why;
  const std::optional<RigidMotion> far =
      valueOrMessage(parseMotionSpec("x,y,z,1152921504606846976,0,0"), &why);
  ASSERT_TRUE(far) << why;
  EXPECT_FALSE(valueOrMessage(moveCase(*p.value, *far, MoveScope::Verdict), &why));
  EXPECT_NE(why.find("not exact in float"), std::string::npos) << why;
  // 1024 keeps every sum exact: moved.
  EXPECT_TRUE(
      valueOrMessage(moveCase(*p.value, *valueOrMessage(parseMotionSpec("x,y,z,1024,0,0"), &why),
                              MoveScope::Verdict),
                     &why))
      << why;
}

}  // namespace
}  // namespace rayspec
