// Rays aimed at the interior vertices, shared edges and faces of a mesh.
#include "case/aim_rays.h"

#include <cmath>
#include <map>
#include <tuple>

#include "base/affine.h"
#include "base/vec3.h"

namespace rayspec {
namespace {

using Pos = std::tuple<float, float, float>;

Pos key(const Vec3& v) {
  return {v[0], v[1], v[2]};
}

}  // namespace

std::vector<DVec3> meshAimPoints(const Geometry& g, const AimSpec& spec) {
  std::vector<DVec3> out;
  if (g.kind != Geometry::Kind::Triangles) return out;
  std::vector<std::array<Vec3, 3>> tris;
  for (uint32_t p = 0; p < g.primitiveCount(); ++p) {
    std::array<Vec3, 3> t;
    bool ok = true;
    for (uint32_t v = 0; v < 3; ++v) {
      const uint32_t i = g.indices.empty() ? p * 3 + v : g.indices[p * 3 + v];
      t[v] = g.vertices[i];
      for (float x : t[v]) ok = ok && !std::isnan(x);
    }
    if (ok) tris.push_back(t);
  }
  // Edges by their two end positions (ordered), in order of first appearance.
  std::map<std::pair<Pos, Pos>, int> edge_use;
  std::vector<std::pair<Vec3, Vec3>> edges;
  std::vector<Vec3> vertices;
  std::map<Pos, bool> seen;
  for (const auto& t : tris)
    for (int e = 0; e < 3; ++e) {
      const Vec3 &a = t[e], &b = t[(e + 1) % 3];
      auto k = key(a) < key(b) ? std::make_pair(key(a), key(b)) : std::make_pair(key(b), key(a));
      if (edge_use[k]++ == 0) edges.push_back({a, b});
      if (!seen.count(key(a))) {
        seen[key(a)] = true;
        vertices.push_back(a);
      }
    }
  auto shared = [&](const Vec3& a, const Vec3& b) {
    auto k = key(a) < key(b) ? std::make_pair(key(a), key(b)) : std::make_pair(key(b), key(a));
    return edge_use[k] == 2;
  };
  if (spec.vertices)
    for (const Vec3& v : vertices) {
      bool closed = true;
      for (const auto& [a, b] : edges)
        if ((key(a) == key(v) || key(b) == key(v)) && !shared(a, b)) closed = false;
      if (closed) out.push_back(toDouble(v));
    }
  if (spec.edges)
    for (const auto& [a, b] : edges) {
      if (!shared(a, b)) continue;
      for (uint32_t k = 1; k <= spec.edge_points; ++k) {
        const double s = double(k) / (spec.edge_points + 1);
        DVec3 p;
        for (int c = 0; c < 3; ++c) p[c] = double(a[c]) + s * (double(b[c]) - double(a[c]));
        out.push_back(p);
      }
    }
  if (spec.faces)
    for (const auto& t : tris) {
      DVec3 p;
      for (int c = 0; c < 3; ++c) p[c] = (double(t[0][c]) + double(t[1][c]) + double(t[2][c])) / 3;
      out.push_back(p);
    }
  return out;
}

Result<std::vector<Ray>> aimRays(const Scene& scene, const AimSpec& spec, const Ray& defaults) {
  std::vector<Ray> rays;
  if (spec.instance >= scene.instances.size() || !scene.instances[spec.instance].blas)
    return errorMessage("instance " + std::to_string(spec.instance) +
                        " is not an instance of a BLAS in the scene");
  const Instance& inst = scene.instances[spec.instance];
  const Blas& blas = scene.blases[*inst.blas];
  if (spec.geometry >= blas.geometries.size() ||
      blas.geometries[spec.geometry].kind != Geometry::Kind::Triangles)
    return errorMessage("geometry " + std::to_string(spec.geometry) + " of BLAS '" + blas.name +
                        "' is not a triangle mesh");
  const Geometry& g = blas.geometries[spec.geometry];
  for (DVec3 p : meshAimPoints(g, spec)) {
    if (g.transform) p = applyAffine(toDouble(*g.transform), p, 1.0);
    p = applyAffine(toDouble(inst.transform), p, 1.0);
    Ray r = defaults;
    for (int k = 0; k < 3; ++k) {
      r.origin[k] = static_cast<float>(p[k] + spec.offset[k]);
      r.direction[k] = static_cast<float>(-spec.offset[k] * spec.direction_scale);
    }
    rays.push_back(r);
  }
  if (rays.empty())
    return errorMessage("the mesh has no interior vertex, shared edge or face to aim at");
  return rays;
}

}  // namespace rayspec
