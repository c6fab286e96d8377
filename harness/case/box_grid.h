// The `aabbs: {grid: ...}` generator: one box per cell of a grid, and the
// `instances` entry `{grid: ...}`: one instance per cell. For builds too
// large to list (accel/size/*): each primitive or instance where a ray of a
// `rays: grid` of the same cells finds it by its index.
#pragma once

#include <array>
#include <cstdint>

#include "case/case.h"

namespace rayspec {

// cells_x * cells_y boxes filling size[0] x size[1], centred at `center`,
// `height` deep around center.z: box (i, j) (row-major, j outer) is
// primitive j * cells_x + i, its faces shared with its neighbours'.
void makeBoxGrid(uint32_t cells_x, uint32_t cells_y, std::array<double, 2> size,
                 std::array<double, 3> center, double height, Geometry& out);

// cells_x * cells_y instances of `proto` (its BLAS, mask, flags, offsets),
// instance (i, j) (row-major, j outer) translated to origin + (i dx, j dy, 0)
// with custom index its position in the grid (mod 2^24).
void appendInstanceGrid(const Instance& proto, uint32_t cells_x, uint32_t cells_y,
                        std::array<double, 2> spacing, std::array<double, 3> origin,
                        std::vector<Instance>& out);

}  // namespace rayspec
