// A ray in a triangle's plane (exact tier, R-PREC). The watertight test's
// determinant is then 0 in exact arithmetic (the triangle seen edge-on), and
// the model's own answer is no hit; but a device's ray lies a few float
// steps off the model's (its object-space ray, its rounding), crosses the
// plane somewhere along the line and may hit the triangle wherever the line
// runs across it: a hit anywhere in that stretch is legal, and so is none.
#pragma once

#include <optional>

#include "base/slab.h"
#include "model/watertight.h"

namespace rayspec {

// The t interval over which the ray's line (in the triangle's plane, to
// rounding: WatertightHit::in_plane) lies within the triangle grown in its
// plane by how far a device's line and triangle may lie from the model's:
//   slack = kDeviceRelTolerance S + |origin error| + (S / |d|) |direction error|
//           + |vertex error|   (infinity norms)
// with S the largest |v - o| (the translated frame the device computes in,
// as watertight.h; the line's points near the triangle lie at t <= S / |d|).
// Empty where the line passes the triangle by more; nullopt where the
// triangle has no plane (zero area: no face to lie in), or where every
// device sees the ray exactly in it (no frame error, a coordinate plane the
// ray runs in: a zero-area projection, culled, R-FACE-DET).
std::optional<Span> inPlaneSpan(const WatertightRay& ray, const DVec3& v0, const DVec3& v1,
                                const DVec3& v2, const DVec3& vertex_err);

// Whether the ray's line lies within inPlaneSpan's slack of the triangle's
// plane along its reach S: the origin's distance from the plane, and the
// direction's part along the normal times S / |d|, both within it (the
// watertight test's in_plane where the determinant is a rounding off 0). A
// ray from far away through the triangle (its origin off the plane) is not
// in it, however much of the triangle its frame error covers.
bool lineNearPlane(const WatertightRay& ray, const DVec3& v0, const DVec3& v1, const DVec3& v2,
                   const DVec3& vertex_err);

}  // namespace rayspec
