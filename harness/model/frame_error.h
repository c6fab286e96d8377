// The device's own view of a triangle test's frame (exact tier, R-PREC): how
// far the object-space ray a device derives from the world ray and an
// instance transform, and the vertices it derives through a geometry
// transform, may lie from the model's. Feeds watertightIntersect's bound.
#pragma once

#include <array>
#include <vector>

#include "case/case.h"
#include "model/watertight.h"

namespace rayspec {

// What a device's inverse of an instance transform (object -> world) costs.
//   Identity: nothing to round; the object ray is the world ray.
//   ScaledPermutation: one non-zero per row and column of the linear part (axis
//     swaps, mirrors, scales): products with powers of two are exact, the
//     others rounded once; the inverse translation is rounded (measured:
//     lavapipe's is off by one float step of the translation), and so is the
//     sum, relative to the small object-space result.
//   General: rotations and shears: the inverse and its application in float
//     (sphere_error.h objectRayError, a few roundings of every magnitude).
enum class InstanceForm { Identity, ScaledPermutation, General };
InstanceForm instanceForm(const Transform& object_to_world);

// Origin and direction parts of the frame error of a world ray seen through
// an instance (inverse: world -> object, row-major 3x4, in double and as the
// float matrix a device may hold).
void objectRayFrameError(InstanceForm form, const std::array<double, 12>& inverse,
                         const std::array<float, 12>& inverse_f, const DVec3& world_origin,
                         const DVec3& world_direction, FrameError& err);

// Per component, the most a device's vertex may differ from the model's when
// both apply the geometry transform `m` to the source vertices in float, each
// in its own order (the largest over the geometry's vertices).
DVec3 geometryVertexError(const Transform& m, const std::vector<Vec3>& vertices);

// How far outside a BLAS's own bounds a device's (and Embree's) object-space
// ray may be off for rays through this instance that start near it (pads the
// model's candidate boxes, model/box_pad.h).
double instancePad(const std::array<double, 12>& inverse, const Transform& object_to_world);

}  // namespace rayspec
