// The base layer (harness/base/): float steps, vectors, 3x4 transforms and
// the slab test, each against values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "base/affine.h"
#include "base/float_steps.h"
#include "base/slab.h"
#include "base/vec3.h"

namespace rayspec {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(FloatSteps, UnitRoundoffIsHalfTheFloatEpsilon) {
  EXPECT_EQ(kUnitRoundoff, std::numeric_limits<float>::epsilon() / 2.0);
  EXPECT_EQ(static_cast<float>(1.0 + kUnitRoundoff), 1.0f) << "a tie rounds to even";
  EXPECT_GT(static_cast<float>(1.0 + 1.5 * kUnitRoundoff), 1.0f);
}

TEST(FloatSteps, NextUpAndDownStepOneFloat) {
  EXPECT_EQ(nextUp(1.0f), 1.0f + std::numeric_limits<float>::epsilon());
  EXPECT_EQ(nextDown(1.0f), 1.0f - std::numeric_limits<float>::epsilon() / 2);
  EXPECT_EQ(nextUp(-1.0f), -nextDown(1.0f));
  EXPECT_EQ(nextUp(0.0f), std::numeric_limits<float>::denorm_min());
  EXPECT_EQ(nextUp(-0.0f), std::numeric_limits<float>::denorm_min());
  EXPECT_EQ(nextDown(0.0f), -std::numeric_limits<float>::denorm_min());
  EXPECT_EQ(nextUp(std::numeric_limits<float>::max()), INFINITY);
  EXPECT_EQ(nextUp(INFINITY), INFINITY);
  EXPECT_EQ(nextDown(-INFINITY), -INFINITY);
  EXPECT_TRUE(std::isnan(nextUp(NAN)));
}

TEST(FloatSteps, DoublesRoundOutwardToFloats) {
  const double third = 1.0 / 3.0;
  EXPECT_LT(floatBelow(third), third);
  EXPECT_GT(floatAbove(third), third);
  EXPECT_EQ(nextUp(floatBelow(third)), floatAbove(third))
      << "neighbours around a double between two floats";
  EXPECT_EQ(floatBelow(0.5), 0.5f) << "a float stays itself";
  EXPECT_EQ(floatAbove(0.5), 0.5f);
  EXPECT_TRUE(std::isnan(floatBelow(NAN)));
}

TEST(Vec3, Operations) {
  const DVec3 x{1, 0, 0}, y{0, 1, 0};
  EXPECT_EQ(cross(x, y), (DVec3{0, 0, 1}));
  EXPECT_EQ(cross(y, x), (DVec3{0, 0, -1}));
  EXPECT_EQ(dot(DVec3{1, 2, 3}, DVec3{4, 5, 6}), 32);
  EXPECT_EQ(length(DVec3{3, 4, 12}), 13);
  EXPECT_EQ(sub(DVec3{5, 5, 5}, DVec3{1, 2, 3}), (DVec3{4, 3, 2}));
  EXPECT_EQ(scaled(DVec3{1, -2, 3}, 2), (DVec3{2, -4, 6}));
  EXPECT_EQ(axpy(DVec3{1, 1, 1}, DVec3{1, 2, 3}, -1), (DVec3{0, -1, -2}));
  EXPECT_EQ(toFloat(DVec3{1.0 / 3.0, 0, 0})[0], 1.0f / 3.0f);
  EXPECT_EQ(toDouble(Vec3{0.1f, 0, 0})[0], double(0.1f));
}

TEST(Affine, PointsMoveAndDirectionsDoNot) {
  // Rotate 90 degrees about z, then translate by (10, 20, 30).
  const Transform m{0, -1, 0, 10, 1, 0, 0, 20, 0, 0, 1, 30};
  EXPECT_EQ(applyAffine(m, Vec3{1, 2, 3}, 1.0f), (Vec3{8, 21, 33}));
  EXPECT_EQ(applyAffine(m, Vec3{1, 2, 3}, 0.0f), (Vec3{-2, 1, 3}));
  EXPECT_EQ(applyAffine(toDouble(m), DVec3{1, 2, 3}, 1.0), (DVec3{8, 21, 33}));
  EXPECT_EQ(applyAffine(kIdentity, Vec3{4, 5, 6}, 1.0f), (Vec3{4, 5, 6}));
  // A direction ignores even a translation of NaN, and keeps +0 where the
  // linear part gives -0.
  const Transform nan_move{-1, 0, 0, NAN, 0, 1, 0, 0, 0, 0, 1, 0};
  const Vec3 d = applyAffine(nan_move, Vec3{0, 1, 0}, 0.0f);
  EXPECT_EQ(d, (Vec3{0, 1, 0}));
  EXPECT_FALSE(std::signbit(d[0]));
  EXPECT_TRUE(std::isnan(applyAffine(nan_move, Vec3{0, 1, 0}, 1.0f)[0]));
}

TEST(Slab, SpanOfALineThroughABox) {
  const DVec3 lo{0, 0, 0}, hi{1, 1, 1};
  Span s = slabSpan(lo, hi, {-1, 0.5, 0.5}, {1, 0, 0});
  EXPECT_EQ(s.t0, 1);
  EXPECT_EQ(s.t1, 2);
  EXPECT_FALSE(s.empty());
  s = slabSpan(lo, hi, {2, 0.5, 0.5}, {-2, 0, 0});  // backwards, and a longer direction
  EXPECT_EQ(s.t0, 0.5);
  EXPECT_EQ(s.t1, 1);
  EXPECT_TRUE(slabSpan(lo, hi, {-1, 2, 0.5}, {1, 0, 0}).empty())
      << "parallel to y's faces, outside them";
  EXPECT_FALSE(slabSpan(lo, hi, {-1, 1, 0.5}, {1, 0, 0}).empty()) << "on a face counts";
  EXPECT_TRUE(slabSpan(lo, hi, {-1, -1, 0.5}, {1, 0.4, 0}).empty()) << "passes by a corner";
  EXPECT_FALSE(slabSpan(lo, hi, {-1, -1, 0.5}, {1, 0.5, 0}).empty())
      << "touches the corner (1, 0): faces count";
  // `within` clips the span: a ray interval that ends before the box.
  EXPECT_TRUE(slabSpan(lo, hi, {-1, 0.5, 0.5}, {1, 0, 0}, {0, 0.5}).empty());
  s = slabSpan(lo, hi, {-1, 0.5, 0.5}, {1, 0, 0}, {1.5, kInf});
  EXPECT_EQ(s.t0, 1.5);
  EXPECT_EQ(s.t1, 2);
  EXPECT_TRUE(slabSpan(lo, hi, {-1, 0.5, 0.5}, {1, 0, 0}, {NAN, kInf}).empty())
      << "a NaN end empties the span";
}

}  // namespace
}  // namespace rayspec
