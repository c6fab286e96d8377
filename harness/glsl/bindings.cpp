#include "glsl/bindings.h"

#include <bit>

namespace rayspec {
namespace {

uint32_t floatBits(float f) {
  return std::bit_cast<uint32_t>(f);
}

}  // namespace

std::vector<uint32_t> packRays(const Rays& rays) {
  std::vector<uint32_t> words(rays.rays.size() * kRayWords, 0u);
  for (size_t i = 0; i < rays.rays.size(); ++i) {
    const Ray& r = rays.rays[i];
    uint32_t* w = words.data() + i * kRayWords;
    for (int k = 0; k < 3; ++k) {
      w[k] = floatBits(r.origin[k]);
      w[4 + k] = floatBits(r.direction[k]);
    }
    w[3] = floatBits(r.tmin);
    w[7] = floatBits(r.tmax);
    w[8] = r.flags;
    w[9] = r.cull_mask;
    w[10] = r.sbt_offset;
    w[11] = r.sbt_stride;
    w[12] = r.miss;
  }
  return words;
}

std::vector<uint32_t> packSceneData(const Scene& scene) {
  const uint32_t n = static_cast<uint32_t>(scene.instances.size());
  std::vector<uint32_t> words(1 + n, kSceneNoTable);
  words[0] = n;
  // One geometry table per AABB BLAS, shared by every instance of it.
  std::vector<uint32_t> table(scene.blases.size(), kSceneNoTable);
  for (size_t b = 0; b < scene.blases.size(); ++b) {
    const Blas& blas = scene.blases[b];
    if (blas.geometries.empty() || blas.geometries.front().kind != Geometry::Kind::Aabbs) continue;
    table[b] = static_cast<uint32_t>(words.size());
    words.resize(words.size() + blas.geometries.size(), 0u);
  }
  for (size_t b = 0; b < scene.blases.size(); ++b) {
    if (table[b] == kSceneNoTable) continue;
    const Blas& blas = scene.blases[b];
    for (size_t g = 0; g < blas.geometries.size(); ++g) {
      words[table[b] + g] = static_cast<uint32_t>(words.size());
      for (const auto& box : blas.geometries[g].aabbs)
        for (float f : box) words.push_back(floatBits(f));
    }
  }
  for (uint32_t i = 0; i < n; ++i) {
    const auto& blas = scene.instances[i].blas;
    if (blas && *blas < table.size()) words[1 + i] = table[*blas];
  }
  return words;
}

}  // namespace rayspec
