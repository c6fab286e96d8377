// How far a device's AABB test may misplace a box's faces (exact tier,
// R-AABB-CONS, R-PREC): a ray the model's exact test sees cross the box
// shrunk by this bound reaches the box's intersection program on every
// device; one that misses the box grown by it reaches it on none; between
// the two a device may offer the box or not (ModelCandidate::near_face,
// ::outside), and the model tries both.
//
// Per axis k of the object-space ray (o, d) the device derives:
//   bound_k = kDeviceRelTolerance max(|lo_k|, |hi_k|, |o|) + boxSlack(lo_k, hi_k)
//             + origin_err_k + T direction_err_k        (|o|: the largest |o_j|)
// 1. The slab test. A float slab test computes each face's t = (b - o_k) / d_k
//    (or times a reciprocal, or fused) with a few roundings relative to
//    |b - o_k| <= 2 max(|b|, |o_k|), then compares t's exactly: the exact
//    test of a box whose faces lie a few u |b - o_k| from the true ones.
//    kDeviceRelTolerance = 16 u covers 8 roundings of |b - o_k|, which is
//    |t d_k| at the face: the bound grows with the origin's magnitude and the
//    distance travelled alike (a ray from 2e6 misjudges a unit box by whole
//    units). Every axis takes the origin's largest component, not its own: a
//    device may test in a frame scaled to the ray's largest coordinate
//    (NVIDIA, fuzz seed 111014: a ray from 5.8e6 in x, its z constant and
//    0.625 object units above a box, ran the box's intersection program).
// 2. The object-space ray. The device's origin and direction lie origin_err
//    and direction_err from the model's (frame_error.h objectRayFrameError;
//    zero for an identity instance); along the ray to the box the direction's
//    error moves the point by at most T direction_err, with T the largest t
//    at which the ray is within the box's reach: T = R / |d|, R the largest
//    |b - o_k| plus the origin part of the bound (infinity norms).
// boxSlack (base/error_bounds.h) is the slack every box had before.
#pragma once

#include "base/vec3.h"
#include "model/watertight.h"

namespace rayspec {

// The bound per axis for the box [lo, hi] and the model's object-space ray
// `ray` (its o, d and the device's origin_err, direction_err).
DVec3 boxFaceBounds(const DVec3& lo, const DVec3& hi, const WatertightRay& ray);

}  // namespace rayspec
