// The `triangles: {grid: ...}` generator: an indexed grid of triangles.
#pragma once

#include <array>
#include <cstdint>

#include "case/case.h"

namespace rayspec {

// cells_x * cells_y cells of size[0] x size[1] in total, centred at `center`, in
// the z = center.z plane. Vertex (i, j) (i along x, j along y, row-major, j
// outer) is shared by its cells (bit-identical). Cell (i, j) holds primitives
// 2 * (j * cells_x + i) = (v(i,j), v(i+1,j), v(i+1,j+1)) and
// 2 * (j * cells_x + i) + 1 = (v(i,j), v(i+1,j+1), v(i,j+1)): counter-clockwise
// seen from +z, so a ray travelling along -z sees front faces.
void makeTriangleGrid(uint32_t cells_x, uint32_t cells_y, std::array<double, 2> size,
                      std::array<double, 3> center, Geometry& out);

}  // namespace rayspec
