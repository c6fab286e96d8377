#include "glsl/bindings.h"

#include <algorithm>
#include <bit>
#include <optional>

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

SbtTables packSbtTables(const Pipeline& p) {
  SbtTables t;
  t.hit_records = static_cast<uint32_t>(p.sbt_hit.empty() ? p.hit_groups.size() : p.sbt_hit.size());
  t.miss_records = static_cast<uint32_t>(p.sbt_miss.empty() ? p.miss.size() : p.sbt_miss.size());
  t.record_words = p.sbt_record_data / 4;
  t.miss_groups = t.hit_groups + t.hit_records;
  t.hit_data = t.miss_groups + t.miss_records;
  t.miss_data = t.hit_data + t.hit_records * t.record_words;
  t.words.assign(std::max<uint32_t>(t.miss_data + t.miss_records * t.record_words, 1), 0u);
  auto group = [](const std::vector<SbtRecord>& list, uint32_t r) -> std::optional<uint32_t> {
    return list.empty() ? std::optional<uint32_t>(r) : list[r].group;
  };
  for (uint32_t r = 0; r < t.hit_records; ++r)
    t.words[t.hit_groups + r] = group(p.sbt_hit, r).value_or(kSbtNoGroup);
  for (uint32_t r = 0; r < t.miss_records; ++r) {
    const std::optional<uint32_t> m = group(p.sbt_miss, r);
    t.words[t.miss_groups + r] = m && *m < p.miss.size() ? *m : kSbtNoGroup;
  }
  auto data = [&](const std::vector<SbtRecord>& list, uint32_t first) {
    for (size_t r = 0; r < list.size(); ++r)
      for (uint32_t w = 0; w < t.record_words && w < list[r].data.size(); ++w)
        t.words[first + r * t.record_words + w] = list[r].data[w];
  };
  data(p.sbt_hit, t.hit_data);
  data(p.sbt_miss, t.miss_data);
  return t;
}

}  // namespace rayspec
