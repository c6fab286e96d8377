// Seeded random triangulation generator.
#include "case/triangulation.h"

#include <algorithm>

#include "case/seeded_random.h"

namespace rayspec {

void makeTriangulation(const TriangulationSpec& spec, Geometry& out) {
  out.kind = Geometry::Kind::Triangles;
  out.vertices.clear();
  out.indices.clear();
  const uint32_t nx = spec.cells_x, ny = spec.cells_y;
  const double jitter = std::clamp(spec.jitter, 0.0, 0.25);
  const double cw = spec.size[0] / nx, ch = spec.size[1] / ny;
  SeededRandom rnd(spec.seed);
  for (uint32_t j = 0; j <= ny; ++j)
    for (uint32_t i = 0; i <= nx; ++i) {
      // Two numbers per vertex whether used or not: a vertex's place depends
      // on the seed and its index only.
      const double jx = rnd.range(-jitter, jitter), jy = rnd.range(-jitter, jitter);
      const bool inner_x = i > 0 && i<nx, inner_y = j> 0 && j < ny;
      const double x = spec.center[0] - spec.size[0] / 2 + cw * (i + (inner_x ? jx : 0));
      const double y = spec.center[1] - spec.size[1] / 2 + ch * (j + (inner_y ? jy : 0));
      out.vertices.push_back(
          {static_cast<float>(x), static_cast<float>(y), static_cast<float>(spec.center[2])});
    }
  auto v = [&](uint32_t i, uint32_t j) {
    return j * (nx + 1) + i;
  };
  for (uint32_t j = 0; j < ny; ++j)
    for (uint32_t i = 0; i < nx; ++i) {
      const uint32_t a = v(i, j), b = v(i + 1, j), c = v(i + 1, j + 1), d = v(i, j + 1);
      if (rnd.coin()) {
        out.indices.insert(out.indices.end(), {a, b, c});
        out.indices.insert(out.indices.end(), {a, c, d});
      } else {
        out.indices.insert(out.indices.end(), {a, b, d});
        out.indices.insert(out.indices.end(), {b, c, d});
      }
    }
}

}  // namespace rayspec
