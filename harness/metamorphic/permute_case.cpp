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
  std::vector<uint32_t> oldOf(n);
  for (uint32_t i = 0; i < n; ++i) oldOf[i] = i;
  if (seen.exact) return oldOf;
  std::map<std::vector<uint64_t>, std::vector<uint32_t>> classes;
  for (uint32_t i = 0; i < n; ++i) classes[seen.classOf(i)].push_back(i);
  for (auto& [key, positions] : classes) {
    std::vector<uint32_t> from = positions;
    shuffle(from, rng);
    for (size_t j = 0; j < positions.size(); ++j) oldOf[positions[j]] = from[j];
  }
  return oldOf;
}

std::vector<uint32_t> anyPermutation(uint32_t n, std::mt19937_64& rng) {
  std::vector<uint32_t> v(n);
  for (uint32_t i = 0; i < n; ++i) v[i] = i;
  shuffle(v, rng);
  return v;
}

void permuteTriangles(Geometry& g, const std::vector<uint32_t>& oldOf, std::mt19937_64& rng) {
  const uint32_t n = static_cast<uint32_t>(oldOf.size());
  if (g.indices.empty()) {
    const std::vector<Vec3> old = g.vertices;
    for (uint32_t p = 0; p < n; ++p)
      for (int k = 0; k < 3; ++k) g.vertices[p * 3 + k] = old[oldOf[p] * 3 + k];
    return;
  }
  const std::vector<uint32_t> oldIndices = g.indices;
  for (uint32_t p = 0; p < n; ++p)
    for (int k = 0; k < 3; ++k) g.indices[p * 3 + k] = oldIndices[oldOf[p] * 3 + k];
  // The vertex buffer too: vertex order is invisible, only the indices say
  // which vertices a triangle shares (bit-identical positions stay so).
  const std::vector<uint32_t> vertexOldOf =
      anyPermutation(static_cast<uint32_t>(g.vertices.size()), rng);
  std::vector<uint32_t> vertexNewOf(vertexOldOf.size());
  for (uint32_t v = 0; v < vertexOldOf.size(); ++v) vertexNewOf[vertexOldOf[v]] = v;
  const std::vector<Vec3> oldVertices = g.vertices;
  for (uint32_t v = 0; v < vertexOldOf.size(); ++v) g.vertices[v] = oldVertices[vertexOldOf[v]];
  for (uint32_t& i : g.indices)
    if (i < vertexNewOf.size()) i = vertexNewOf[i];  // an index out of range stays out of range
}

bool moved(const std::vector<uint32_t>& oldOf) {
  for (uint32_t i = 0; i < oldOf.size(); ++i)
    if (oldOf[i] != i) return true;
  return false;
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
  const IdObservations primitives = observeId(c.pipeline, "primitive_id");
  const IdObservations instances = observeId(c.pipeline, "instance_id");
  Scene& scene = out.permuted.scene;
  out.primitive_of.resize(scene.blases.size());
  for (size_t b = 0; b < scene.blases.size(); ++b) {
    for (Geometry& g : scene.blases[b].geometries) {
      const std::vector<uint32_t> oldOf = classPermutation(g.primitiveCount(), primitives, rng);
      if (g.kind == Geometry::Kind::Aabbs) {
        const auto old = g.aabbs;
        for (uint32_t p = 0; p < oldOf.size(); ++p) g.aabbs[p] = old[oldOf[p]];
      } else {
        permuteTriangles(g, oldOf, rng);
      }
      out.primitive_of[b].push_back(oldOf);
    }
  }
  out.instance_of = classPermutation(static_cast<uint32_t>(scene.instances.size()), instances, rng);
  const std::vector<Instance> old = scene.instances;
  for (size_t i = 0; i < old.size(); ++i) scene.instances[i] = old[out.instance_of[i]];
  return out;
}

}  // namespace rayspec
