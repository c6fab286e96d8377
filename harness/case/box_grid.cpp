// Box and instance grid generators.
#include "case/box_grid.h"

namespace rayspec {

void makeBoxGrid(uint32_t nx, uint32_t ny, std::array<double, 2> size, std::array<double, 3> center,
                 double height, Geometry& out) {
  out.kind = Geometry::Kind::Aabbs;
  out.aabbs.clear();
  out.aabbs.reserve(static_cast<size_t>(nx) * ny);
  // Cell edges computed once, so that neighbours share them bit for bit.
  auto edge = [](double lo, double extent, uint32_t k, uint32_t n) {
    return static_cast<float>(lo + extent * k / n);
  };
  const double x0 = center[0] - size[0] / 2, y0 = center[1] - size[1] / 2;
  const float z0 = static_cast<float>(center[2] - height / 2);
  const float z1 = static_cast<float>(center[2] + height / 2);
  for (uint32_t j = 0; j < ny; ++j)
    for (uint32_t i = 0; i < nx; ++i)
      out.aabbs.push_back({edge(x0, size[0], i, nx), edge(y0, size[1], j, ny), z0,
                           edge(x0, size[0], i + 1, nx), edge(y0, size[1], j + 1, ny), z1});
}

void appendInstanceGrid(const Instance& proto, uint32_t nx, uint32_t ny,
                        std::array<double, 2> spacing, std::array<double, 3> origin,
                        std::vector<Instance>& out) {
  for (uint32_t j = 0; j < ny; ++j)
    for (uint32_t i = 0; i < nx; ++i) {
      Instance inst = proto;
      inst.transform = {1, 0, 0, static_cast<float>(origin[0] + spacing[0] * i),
                        0, 1, 0, static_cast<float>(origin[1] + spacing[1] * j),
                        0, 0, 1, static_cast<float>(origin[2])};
      inst.custom_index = (j * nx + i) & kInstanceFieldMask;
      out.push_back(inst);
    }
}

}  // namespace rayspec
