// When the open ends of a triangle's interval are judged exactly (exact tier,
// R-CAND-TRI-OPEN): if every reasonable float algorithm computes a
// candidate's t exactly, a device's comparison of t with tmin and tmax is as
// exact as the model's, and a triangle at t == tmax or t == tmin is no tie:
// it is no candidate.
//
// The criterion (all of it must hold):
//  1. The object-space ray is the same on every device: the instance
//     transform is the identity, or its linear part is a signed permutation
//     of powers of two (an exact inverse) and its entries, its translation
//     and the world origin lie on one small grid (below); the direction has
//     one non-zero component, a power of two. No geometry transform.
//  2. The triangle lies in a plane perpendicular to that axis (its three
//     vertices share that coordinate).
//  3. The object-space origin, the vertices and t lie on one small grid: all
//     are integer multiples of 2^q and at most 2^Q in magnitude, with
//     Q - q <= kExactGridBits. Then every difference of two of them, every
//     product of three such differences and every sum of up to eight of those
//     (Moller-Trumbore's, Woop's and the plane-equation forms of t's
//     numerator and denominator are all such) fits in 24 bits: a float
//     computes them exactly, in any order, with or without FMA; a direction
//     of a power of two only scales them.
//  4. A device that multiplies N by a rounded reciprocal of D instead of
//     dividing gets t too: N = A (v - o), D = A d up to powers of two (A the
//     doubled area of the triangle's projection), and A is a power of two,
//     or (A (v - o)) * rcp(A) rounds to v - o for the correctly rounded
//     reciprocal and for one a float step off either way. (Vertex (10.25, 0, 0) with (0, 0, 0) and
//     (0, 1, 0): A = 41, and t = 1 comes out 1 - 2^-24.)
// Then t's numerator N and denominator D are exact, N / D is t, and a device
// either divides (correctly rounded: t itself), multiplies by the reciprocal
// (4), or compares N with the
// interval end times D. That product is exact too when the end lies on the
// same grid; when it does not, the comparison is still exact on the side
// where t is at or beyond the end (rounding is monotonic and N is a float).
#pragma once

#include "case/case.h"
#include "model/frame_error.h"
#include "model/watertight.h"

namespace rayspec {

constexpr int kExactGridBits = 6;  // 3 * (Q - q + 1) + 3 <= 24

// Criterion 1 for the world ray through this instance.
bool objectRayExact(InstanceForm form, const Transform& object_to_world, const DVec3& world_origin);

// Criteria 2 and 3 for the object-space ray o + t d and the triangle, and
// whether a device's comparison with each end of [tmin, tmax] is exact.
struct ExactEnds {
  bool tmin = false, tmax = false;
};
ExactEnds exactEnds(const DVec3& o, const DVec3& d, const DVec3& v0, const DVec3& v1,
                    const DVec3& v2, double t, double tmin, double tmax);

}  // namespace rayspec
