// Error bounds of the sphere ops (sphere_hit, sphere_near, sphere_far) for the
// exact tier (R-PREC): a device computes gl_ObjectRayOriginEXT / DirectionEXT
// from the world ray and the instance transform with its own rounding (and
// its own inverse), then the float formulas of shaders/sphere.glsl. These
// bounds say how far its discriminant and roots may lie from the model's.
#pragma once

#include <array>

#include "model/model_shading.h"

namespace rayspec {

// Per component, the most a device's object-space origin / direction may
// differ from the model's: a few float roundings of the inverse and of the
// transform, relative to the magnitudes summed (row-major 3x4 world->object).
struct ObjectRayError {
  Vec3 origin{}, direction{};
};
ObjectRayError objectRayError(const std::array<float, 12>& inverse, const Vec3& world_origin,
                              const Vec3& world_direction);

struct SphereError {
  double disc = 0;                   // the model's float discriminant, widened
  double disc_err = 0;               // bound on |device disc - model disc|
  double near_err = 0, far_err = 0;  // bounds on the roots' differences
};
// The model's terms (sphereRoots) for the object ray o + t d with the
// perturbation `e` of o and d, each later float operation rounded anew.
SphereError sphereError(const Vec3& bmin, const Vec3& bmax, const Vec3& o, const Vec3& d,
                        const ObjectRayError& e);

}  // namespace rayspec
