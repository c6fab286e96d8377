// Indexed triangle grid generator.
#include "case/triangle_grid.h"

namespace rayspec {

void makeTriangleGrid(uint32_t nx, uint32_t ny, std::array<double, 2> size,
                      std::array<double, 3> center, Geometry& out) {
  out.kind = Geometry::Kind::Triangles;
  out.vertices.clear();
  out.indices.clear();
  for (uint32_t j = 0; j <= ny; ++j)
    for (uint32_t i = 0; i <= nx; ++i) {
      const double x = center[0] - size[0] / 2 + size[0] * i / nx;
      const double y = center[1] - size[1] / 2 + size[1] * j / ny;
      out.vertices.push_back(
          {static_cast<float>(x), static_cast<float>(y), static_cast<float>(center[2])});
    }
  auto v = [&](uint32_t i, uint32_t j) {
    return j * (nx + 1) + i;
  };
  for (uint32_t j = 0; j < ny; ++j)
    for (uint32_t i = 0; i < nx; ++i) {
      out.indices.insert(out.indices.end(), {v(i, j), v(i + 1, j), v(i + 1, j + 1)});
      out.indices.insert(out.indices.end(), {v(i, j), v(i + 1, j + 1), v(i, j + 1)});
    }
}

}  // namespace rayspec
