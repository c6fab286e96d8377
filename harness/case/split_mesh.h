// scene.split: a triangle mesh's triangles each in a geometry of its own (one
// bottom level, one geometry a triangle) or each in a bottom level and an
// instance of its own (the CTS's closedFan2), every world position bit
// identical to the mesh's (R-WATERTIGHT across geometries and instances).
#pragma once

#include <array>
#include <cstdint>

#include "base/result.h"
#include "case/case.h"

namespace rayspec {

struct SplitSpec {
  enum class Into { Geometries, Instances };
  uint32_t blas = 0;  // index into Scene::blases: one triangle geometry
  Into into = Into::Geometries;
  // Instances: instance k is translated by (k % 2) * translate and, with
  // cycle_axes, its axes cycled k % 3 times (x -> y -> z, a rotation), its
  // triangle's object positions the inverse of that applied to the mesh's
  // (an error where one is not exact in float).
  std::array<float, 3> translate{0, 0, 0};
  bool cycle_axes = false;
};

// Splits blases[spec.blas] (its one geometry: float3 vertices, any indices);
// Geometries: into one geometry per triangle, each with the geometry's flags
// and transform, in primitive order. Instances: every instance of it becomes
// one instance per triangle (the bottom level k its triangle k; the
// instance's fields kept, its transform the one above: the instance must
// have the identity transform and the geometry none). An error naming what
// does not fit.
Result<void> splitMesh(Scene& scene, const SplitSpec& spec);

// The 3x4 transform of instance k under `spec` (Instances).
Transform splitTransform(const SplitSpec& spec, uint32_t k);

}  // namespace rayspec
