// How far the model's candidate boxes for its own triangle tests are padded
// (exact tier, model_scene.cpp ownTriangleBounds), per BLAS: every triangle
// whose exact test may answer a hit or an ambiguity for some ray of the case
// must be enumerated by Embree, and no more (each extra candidate costs a
// triangle test). The argument is in box_pad.cpp.
#pragma once

#include <vector>

#include "case/case.h"

namespace rayspec {

// Float steps (2^-24) of the triangle's own coordinates' magnitude added to
// every pad (ownTriangleBounds).
constexpr double kBoxMagnitudeSteps = 4.0;

// Per BLAS of the case: the object-space pad (absolute) for rays through any
// of its instances: the ray's error (the device's and Embree's object-space
// ray, Embree's float traversal) and the reach of the exact test's ambiguity
// zone. Index = BLAS index; 0 for a BLAS no instance uses. Over more than
// `exact_pairs` instance-origin pairs the origins' bounding box corners stand
// in for the origins (pads as large or larger).
constexpr double kExactPadPairs = double(1 << 24);  // about 0.2 s
std::vector<double> blasRayPads(const Case& c, double exact_pairs = kExactPadPairs);

// Per BLAS of the case: how far its AABBs are grown for Embree (exact tier,
// model_scene.cpp aabbBounds), so that every box within a device's error
// bound of a ray (model/box_bound.h; ModelCandidate::outside) is enumerated.
// Over the ray origins as blasRayPads takes them and the instances of the
// BLAS, uncapped (a box a far ray may be offered is enumerated, however far):
//   kDeviceRelTolerance max(|o|, M) + |origin error| + (|q| + W) |direction error|
// with o the object-space origin, q the world one, M and W the BLAS box's
// largest coordinate in object and world space (W + |q| bounds how far the
// ray travels to it), the frame errors for a direction of (1, 1, 1) (they
// grow with it linearly); times kBoxPadMargin for Embree's own float object
// ray (the same roundings as a device's) and traversal. 0 for a case
// without AABBs.
constexpr double kBoxPadMargin = 2.0;
std::vector<double> blasBoxPads(const Case& c, double exact_pairs = kExactPadPairs);

}  // namespace rayspec
