// The numeric slacks and tolerances the model and the comparison write by
// hand, named once. Each is a fixed number (its value is part of what every
// saved result was judged with, so it stays exactly as it was written); the
// comments say how it relates to float rounding and, where the number was
// chosen by trial rather than derived, say that too.
//
// Written the way pbrt-v4 writes its bounds: n roundings of relative error u
// (u = 2^-24, base/float_steps.h) compound to at most
//   gamma(n) = n u / (1 - n u)   (errorGamma below),
// so a relative slack s "covers n roundings" when s >= gamma(n). The static
// asserts below pin each slack to the rounding count it stands for.
#pragma once

#include <algorithm>
#include <cmath>

#include "base/float_steps.h"

namespace rayspec {

// The bound on the relative error of n compounded float roundings.
constexpr double errorGamma(int n) {
  return n * kUnitRoundoff / (1 - n * kUnitRoundoff);
}

// The floor under a magnitude that scales a relative slack: max(|x|, floor).
// Without it a box face or a region at exactly 0 would get no slack at all.
// 1e-30 is far below any magnitude a scene uses in earnest and far above
// 0 (the smallest normal float is ~1.2e-38), so it decides the slack only
// where every magnitude is (nearly) 0. A choice, not a derivation.
constexpr double kMagnitudeFloor = 1e-30;
constexpr float kMagnitudeFloorF = 1e-30f;

// The relative slack a box is grown by before a ray is tested against it
// (R-AABB-CONS: a conservative box; the NaN triangle's region), so that a
// ray grazing a face is still enumerated and the model decides it itself.
// 1e-6 ~ 16.8 u: just above gamma(16), the 16 roundings kDeviceRelTolerance
// (model/watertight.h) grants a device outside the translated frame. The
// margin over it was not derived; it was chosen and has held on every case.
constexpr double kBoxSlackRel = 1e-6;
constexpr float kBoxSlackRelF = 1e-6f;
static_assert(kBoxSlackRel > errorGamma(16) && kBoxSlackRel < errorGamma(17));

// The box slack of an axis whose faces are lo and hi:
// kBoxSlackRel * max(|lo|, |hi|, kMagnitudeFloor).
inline double boxSlack(double lo, double hi) {
  return kBoxSlackRel * std::max({std::fabs(lo), std::fabs(hi), kMagnitudeFloor});
}
// The same in float, for Embree's float bounds (computed in float as it was).
inline float boxSlackF(float lo, float hi) {
  return std::max({std::fabs(lo), std::fabs(hi), kMagnitudeFloorF}) * kBoxSlackRelF;
}

// The relative padding of what the model hands Embree to enumerate: the
// trace's [tmin, tmax] (the model checks both ends itself, so Embree's
// interval only has to include every candidate near them) and a NaN
// triangle's region. 1e-5 ~ 168 u, about gamma(168): ten times the box
// slack, so a candidate within a device's error of an end is never lost to
// Embree's own float rounding of t. Empirical margin, not a tight bound:
// any padding that covers Embree's rounding gives the same answers (the
// model re-decides every candidate it is handed).
constexpr double kEnumerationPadRel = 1e-5;
constexpr float kEnumerationPadRelF = 1e-5f;
static_assert(kEnumerationPadRel > errorGamma(167) && kEnumerationPadRel < errorGamma(168));

// The documented tolerances of float fields (results/tolerances.h): a device
// value d matches the model's m when |d - m| <= abs + rel * max(|m|, 1). The
// specification promises no bound (R-PREC); these are the suite's own.
//
// Most fields (t, ray parameters, positions, directions): 1e-5 absolute and
// relative, about gamma(168): a few float operations on values of order 1
// need gamma(n) for n of about 10; the rest is headroom for a device's
// different but legal operation order. Empirical: chosen once, not derived
// from an operation count.
constexpr double kFieldTolerance = 1e-5;
// Barycentrics: 1e-4 absolute (no relative part: they lie in [0, 1]). A
// float32 edge function on a unit-size triangle divided by their sum loses
// digits where an edge function is small; 1e-4 was chosen to cover that
// with room, not derived.
constexpr double kBarycentricTolerance = 1e-4;
// Colours: 1e-4 absolute and relative. The lights divide by d^2, which
// magnifies the error of d; chosen, not derived.
constexpr double kColorTolerance = 1e-4;
static_assert(kFieldTolerance > errorGamma(167) && kBarycentricTolerance > 10 * errorGamma(167));

}  // namespace rayspec
