// The `triangles: {fan: ...}` generator: a closed fan of triangles around one
// centre vertex, seeded.
#pragma once

#include <array>
#include <cstdint>

#include "case/case.h"

namespace rayspec {

struct FanSpec {
  uint32_t triangles = 8;                 // at least 3
  double radius = 1;                      // of the rim
  std::array<double, 3> center{0, 0, 0};  // the fan lies in the z = center.z plane
  uint64_t seed = 0;                      // 0: a regular fan; else rim angles and radii jittered
};

// Vertex 0 is the centre, vertices 1..n the rim in counter-clockwise order
// (seen from +z); primitive k = (0, 1 + k, 1 + (k + 1) % n), counter-clockwise,
// so every spoke is shared by two triangles and the centre closed all around.
// With a seed, rim angle k is 2 pi (k + u) / n with u in [-0.3, 0.3] and its
// radius in [0.6, 1] * radius (SeededRandom: the same fan for a seed everywhere).
void makeTriangleFan(const FanSpec& spec, Geometry& out);

}  // namespace rayspec
