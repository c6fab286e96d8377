#include "metamorphic/permute_case.h"

#include <map>
#include <random>

#include "metamorphic/id_observations.h"
#include "results/content_hash.h"

namespace rayspec {
namespace {

// Fisher-Yates with the standard's mt19937_64 (the same order on every
// platform, unlike std::shuffle).
void shuffle(std::vector<uint32_t>& v, std::mt19937_64& rng) {
  for (size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng() % i]);
}

// new index -> old index, each id kept in its class.
std::vector<uint32_t> classPermutation(uint32_t n, const IdObservations& seen,
                                       std::mt19937_64& rng) {
  std::vector<uint32_t> old_of(n);
  for (uint32_t i = 0; i < n; ++i) old_of[i] = i;
  if (seen.exact) return old_of;
  std::map<std::vector<uint64_t>, std::vector<uint32_t>> classes;
  for (uint32_t i = 0; i < n; ++i) classes[seen.classOf(i)].push_back(i);
  for (auto& [key, positions] : classes) {
    std::vector<uint32_t> from = positions;
    shuffle(from, rng);
    for (size_t j = 0; j < positions.size(); ++j) old_of[positions[j]] = from[j];
  }
  return old_of;
}

std::vector<uint32_t> anyPermutation(uint32_t n, std::mt19937_64& rng) {
  std::vector<uint32_t> v(n);
  for (uint32_t i = 0; i < n; ++i) v[i] = i;
  shuffle(v, rng);
  return v;
}

bool moved(const std::vector<uint32_t>& old_of) {
  for (uint32_t i = 0; i < old_of.size(); ++i)
    if (old_of[i] != i) return true;
  return false;
}

// Whether the vertex buffer moved (an indexed geometry's is shuffled too).
bool permuteTriangles(Geometry& g, const std::vector<uint32_t>& old_of, std::mt19937_64& rng) {
  const uint32_t n = static_cast<uint32_t>(old_of.size());
  if (g.indices.empty()) {
    const std::vector<Vec3> old = g.vertices;
    for (uint32_t p = 0; p < n; ++p)
      for (int k = 0; k < 3; ++k) g.vertices[p * 3 + k] = old[old_of[p] * 3 + k];
    return false;
  }
  const std::vector<uint32_t> old_indices = g.indices;
  for (uint32_t p = 0; p < n; ++p)
    for (int k = 0; k < 3; ++k) g.indices[p * 3 + k] = old_indices[old_of[p] * 3 + k];
  // The vertex buffer too: vertex order is invisible, only the indices say
  // which vertices a triangle shares (bit-identical positions stay so).
  const std::vector<uint32_t> vertex_old_of =
      anyPermutation(static_cast<uint32_t>(g.vertices.size()), rng);
  std::vector<uint32_t> vertex_new_of(vertex_old_of.size());
  for (uint32_t v = 0; v < vertex_old_of.size(); ++v) vertex_new_of[vertex_old_of[v]] = v;
  const std::vector<Vec3> old_vertices = g.vertices;
  for (uint32_t v = 0; v < vertex_old_of.size(); ++v)
    g.vertices[v] = old_vertices[vertex_old_of[v]];
  for (uint32_t& i : g.indices)
    if (i < vertex_new_of.size()) i = vertex_new_of[i];  // an index out of range stays out of range
  return moved(vertex_old_of);
}

}  // namespace

bool CasePermutation::primitivesMoved() const {
  for (const auto& blas : primitive_of)
    for (const auto& geometry : blas)
      if (moved(geometry)) return true;
  return false;
}

bool CasePermutation::instancesMoved() const {
  return moved(instance_of);
}

CasePermutation permuteCase(const Case& c, uint64_t seed) {
  CasePermutation out;
  out.seed = seed;
  out.permuted = c;
  // A bundle of the permuted case is not one of the case as written.
  out.permuted.source_hash = contentHash(c.source_hash, &seed, sizeof seed);
  std::mt19937_64 rng(seed);
  const IdObservations primitives = observeId(c.pipeline, kBiPrimitive);
  const IdObservations instances = observeId(c.pipeline, kBiInstance);
  Scene& scene = out.permuted.scene;
  out.primitive_of.resize(scene.blases.size());
  for (size_t b = 0; b < scene.blases.size(); ++b) {
    for (Geometry& g : scene.blases[b].geometries) {
      const std::vector<uint32_t> old_of = classPermutation(g.primitiveCount(), primitives, rng);
      if (g.kind == Geometry::Kind::Aabbs) {
        const auto old = g.aabbs;
        for (uint32_t p = 0; p < old_of.size(); ++p) g.aabbs[p] = old[old_of[p]];
      } else if (permuteTriangles(g, old_of, rng)) {
        out.vertices_moved = true;
      }
      out.primitive_of[b].push_back(old_of);
    }
  }
  out.instance_of = classPermutation(static_cast<uint32_t>(scene.instances.size()), instances, rng);
  const std::vector<Instance> old = scene.instances;
  for (size_t i = 0; i < old.size(); ++i) scene.instances[i] = old[out.instance_of[i]];
  return out;
}

}  // namespace rayspec
