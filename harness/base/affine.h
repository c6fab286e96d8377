// Row-major 3x4 affine transforms (instance and geometry transforms, as
// VkTransformMatrixKHR holds them) applied to points (w = 1) and directions
// (w = 0), in float as a device stores them or in double as the model
// computes.
#pragma once

#include <array>

#include "base/vec3.h"

namespace rayspec {

using Transform = std::array<float, 12>;
using DTransform = std::array<double, 12>;
constexpr Transform kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

// Row r: m[4r] v0 + m[4r+1] v1 + m[4r+2] v2, plus m[4r+3] w for a point
// (w != 0) and plus +0 for a direction (w = 0: a translation of inf or NaN
// leaves it finite), summed left to right in the precision of the arguments.
Vec3 applyAffine(const Transform& m, const Vec3& v, float w);
DTransform toDouble(const Transform& m);  // exact
DVec3 applyAffine(const DTransform& m, const DVec3& v, double w);

}  // namespace rayspec
