// The named error bounds (base/error_bounds.h): each keeps exactly the value
// the model and the comparison wrote by hand before it was named, and the
// box slack is computed as it was (in double, and in float for Embree).
#include "base/error_bounds.h"

#include <gtest/gtest.h>

namespace rayspec {
namespace {

TEST(ErrorBounds, GammaIsNRoundingsOverOneMinusThem) {
  EXPECT_DOUBLE_EQ(errorGamma(1), kUnitRoundoff / (1 - kUnitRoundoff));
  EXPECT_DOUBLE_EQ(errorGamma(16), 16 * kUnitRoundoff / (1 - 16 * kUnitRoundoff));
  EXPECT_GT(errorGamma(16), 16 * kUnitRoundoff);  // compounding costs a little more than n u
  EXPECT_LT(errorGamma(16), errorGamma(17));
}

TEST(ErrorBounds, TheNamedValuesAreTheOnesWrittenBefore) {
  EXPECT_EQ(kMagnitudeFloor, 1e-30);
  EXPECT_EQ(kMagnitudeFloorF, 1e-30f);
  EXPECT_EQ(kBoxSlackRel, 1e-6);
  EXPECT_EQ(kBoxSlackRelF, 1e-6f);
  EXPECT_EQ(kEnumerationPadRel, 1e-5);
  EXPECT_EQ(kEnumerationPadRelF, 1e-5f);
  EXPECT_EQ(kFieldTolerance, 1e-5);
  EXPECT_EQ(kBarycentricTolerance, 1e-4);
  EXPECT_EQ(kColorTolerance, 1e-4);
}

TEST(ErrorBounds, BoxSlackScalesWithTheLargerFaceAndNeverVanishes) {
  EXPECT_EQ(boxSlack(-3.0, 2.0), 1e-6 * 3.0);
  EXPECT_EQ(boxSlack(1.0, 4.0), 1e-6 * 4.0);
  EXPECT_EQ(boxSlack(0.0, -0.0), 1e-6 * 1e-30);
  EXPECT_GT(boxSlack(0.0, 0.0), 0.0);
}

TEST(ErrorBounds, FloatBoxSlackIsComputedInFloat) {
  EXPECT_EQ(boxSlackF(-3.0f, 2.0f), 3.0f * 1e-6f);
  EXPECT_EQ(boxSlackF(0.0f, 0.0f), 1e-30f * 1e-6f);
  // In float the product rounds to float, not to the double 3e-6.
  EXPECT_EQ(static_cast<double>(boxSlackF(3.0f, 0.0f)), static_cast<double>(3.0f * 1e-6f));
}

}  // namespace
}  // namespace rayspec
