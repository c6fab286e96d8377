// The `triangles: {triangulation: ...}` generator: a seeded random
// triangulation of a rectangle.
#pragma once

#include <array>
#include <cstdint>

#include "case/case.h"

namespace rayspec {

struct TriangulationSpec {
  uint32_t cells_x = 4, cells_y = 4;
  std::array<double, 2> size{1, 1};
  std::array<double, 3> center{0, 0, 0};  // in the z = center.z plane
  uint64_t seed = 1;
  double jitter = 0.25;  // at most 0.25 (of a cell): every cell stays convex
};

// The grid of case/triangle_grid.h (same vertex order) with every vertex
// moved by up to `jitter` cells in x and y (vertices on the border only
// along it, corners not at all, so the outline stays the rectangle), and
// each cell split along a diagonal chosen at random: cell (i, j) holds
// primitives 2 (j cells_x + i) and 2 (j cells_x + i) + 1, both
// counter-clockwise seen from +z. SeededRandom: the same mesh for a seed
// everywhere.
void makeTriangulation(const TriangulationSpec& spec, Geometry& out);

}  // namespace rayspec
