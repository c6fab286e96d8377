// Building instance / geometry transforms (row-major 3x4) from their parts.
#pragma once

#include <array>

#include "base/affine.h"
#include "base/vec3.h"
#include "case/case.h"

namespace rayspec {

struct TransformParts {
  DVec3 translate{0, 0, 0};
  DVec3 scale{1, 1, 1};
  DVec3 axis{0, 0, 1};  // rotation axis (normalised here; must not be zero)
  double degrees = 0;   // rotation angle, right-handed about axis
};

// translate * rotate * scale, computed in double, stored as float.
Transform composeTransform(const TransformParts& p);

// Determinant of the 3x3 linear part (0 = not invertible).
double linearDeterminant(const Transform& t);

// The inverse (world -> object for an instance), row-major 3x4, in double;
// all zero when the linear part is not invertible.
DTransform invertTransform(const Transform& m);

}  // namespace rayspec
