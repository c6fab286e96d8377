// Closed triangle fan generator.
#include "case/triangle_fan.h"

#include <cmath>

#include "case/seeded_random.h"

namespace rayspec {

void makeTriangleFan(const FanSpec& spec, Geometry& out) {
  out.kind = Geometry::Kind::Triangles;
  out.vertices.clear();
  out.indices.clear();
  const auto& c = spec.center;
  out.vertices.push_back(
      {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])});
  SeededRandom rnd(spec.seed);
  const uint32_t n = spec.triangles;
  constexpr double kTwoPi = 6.283185307179586476925;
  for (uint32_t k = 0; k < n; ++k) {
    double angle = kTwoPi * k / n, radius = spec.radius;
    if (spec.seed) {
      angle = kTwoPi * (k + rnd.range(-0.3, 0.3)) / n;
      radius *= rnd.range(0.6, 1.0);
    }
    out.vertices.push_back({static_cast<float>(c[0] + radius * std::cos(angle)),
                            static_cast<float>(c[1] + radius * std::sin(angle)),
                            static_cast<float>(c[2])});
  }
  for (uint32_t k = 0; k < n; ++k)
    out.indices.insert(out.indices.end(), {0u, 1 + k, 1 + (k + 1) % n});
}

}  // namespace rayspec
