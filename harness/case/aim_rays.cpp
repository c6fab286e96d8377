// Rays aimed at the interior vertices, shared edges and faces of a mesh.
#include "case/aim_rays.h"

#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "base/affine.h"
#include "base/vec3.h"

namespace rayspec {
namespace {

using Pos = std::tuple<float, float, float>;

Pos key(const Vec3& v) {
  return {v[0], v[1], v[2]};
}

// Each every-th target of each feature, from the first.
std::vector<AimTarget> everyNth(std::vector<AimTarget> all, uint32_t every) {
  if (every <= 1) return all;
  std::vector<AimTarget> out;
  std::map<AimFeature, uint32_t> seen;
  for (AimTarget& t : all)
    if (seen[t.feature]++ % every == 0) out.push_back(std::move(t));
  return out;
}

// The triangles without a NaN, each with its primitive index.
struct MeshTriangles {
  std::vector<std::array<Vec3, 3>> tris;
  std::vector<uint32_t> ids;
};

MeshTriangles usableTriangles(const Geometry& g) {
  MeshTriangles m;
  for (uint32_t p = 0; p < g.primitiveCount(); ++p) {
    std::array<Vec3, 3> t;
    bool ok = true;
    for (uint32_t v = 0; v < 3; ++v) {
      const uint32_t i = g.indices.empty() ? p * 3 + v : g.indices[p * 3 + v];
      t[v] = g.vertices[i];
      for (float x : t[v]) ok = ok && !std::isnan(x);
    }
    if (ok) {
      m.tris.push_back(t);
      m.ids.push_back(p);
    }
  }
  return m;
}

// The closed vertices and the points on shared edges, appended to `out`.
// Edges by their two end positions (ordered), in order of first appearance,
// each with the triangles that have it; vertices likewise.
void vertexAndEdgeTargets(const MeshTriangles& m, const AimSpec& spec,
                          std::vector<AimTarget>& out) {
  using EdgeKey = std::pair<Pos, Pos>;
  std::map<EdgeKey, std::vector<uint32_t>> edge_tris;
  std::vector<std::pair<Vec3, Vec3>> edges;
  std::vector<Vec3> vertices;
  std::map<Pos, std::vector<uint32_t>> vertex_tris;
  const auto edge_key = [](const Vec3& a, const Vec3& b) {
    return key(a) < key(b) ? std::make_pair(key(a), key(b)) : std::make_pair(key(b), key(a));
  };
  for (size_t t = 0; t < m.tris.size(); ++t)
    for (int e = 0; e < 3; ++e) {
      const Vec3 &a = m.tris[t][e], &b = m.tris[t][(e + 1) % 3];
      std::vector<uint32_t>& users = edge_tris[edge_key(a, b)];
      if (users.empty()) edges.push_back({a, b});
      users.push_back(m.ids[t]);
      std::vector<uint32_t>& at = vertex_tris[key(a)];
      if (at.empty()) vertices.push_back(a);
      if (at.empty() || at.back() != m.ids[t]) at.push_back(m.ids[t]);
    }
  auto shared = [&](const Vec3& a, const Vec3& b) {
    return edge_tris[edge_key(a, b)].size() == 2;
  };
  // A vertex is open where one of its edges is not shared (one pass over
  // the edges: meshes of 2^16 triangles and more are aimed at too).
  std::set<Pos> open;
  for (const auto& [a, b] : edges) {
    if (shared(a, b)) continue;
    open.insert(key(a));
    open.insert(key(b));
  }
  if (spec.vertices)
    for (const Vec3& v : vertices)
      if (!open.count(key(v)))
        out.push_back({AimFeature::Vertex, 0, 0, vertex_tris[key(v)], toDouble(v), {}});
  if (spec.edges)
    for (const auto& [a, b] : edges) {
      if (!shared(a, b)) continue;
      for (uint32_t k = 1; k <= spec.edge_points; ++k) {
        const double s = double(k) / (spec.edge_points + 1);
        DVec3 p;
        for (int c = 0; c < 3; ++c) p[c] = double(a[c]) + s * (double(b[c]) - double(a[c]));
        out.push_back({AimFeature::Edge, 0, 0, edge_tris[edge_key(a, b)], p, {}});
      }
    }
}

}  // namespace

std::vector<AimTarget> meshAimTargets(const Geometry& g, const AimSpec& spec) {
  std::vector<AimTarget> out;
  if (g.kind != Geometry::Kind::Triangles) return out;
  const MeshTriangles m = usableTriangles(g);
  // The mesh's edges and vertices are sorted out only where they are aimed
  // at (accel/size-triangles aims at the faces of 2^20 triangles alone).
  if (spec.vertices || spec.edges) vertexAndEdgeTargets(m, spec, out);
  if (spec.faces)
    for (size_t t = 0; t < m.tris.size(); ++t) {
      DVec3 p;
      for (int c = 0; c < 3; ++c)
        p[c] = (double(m.tris[t][0][c]) + double(m.tris[t][1][c]) + double(m.tris[t][2][c])) / 3;
      out.push_back({AimFeature::Face, 0, 0, {m.ids[t]}, p, {}});
    }
  return everyNth(std::move(out), spec.every);
}

std::vector<DVec3> meshAimPoints(const Geometry& g, const AimSpec& spec) {
  std::vector<DVec3> out;
  for (const AimTarget& t : meshAimTargets(g, spec)) out.push_back(t.object);
  return out;
}

Result<std::vector<Ray>> aimRays(const Scene& scene, const AimSpec& spec, const Ray& defaults,
                                 std::vector<AimTarget>* targets) {
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
  for (AimTarget& target : meshAimTargets(g, spec)) {
    DVec3 p = target.object;
    if (g.transform) p = applyAffine(toDouble(*g.transform), p, 1.0);
    p = applyAffine(toDouble(inst.transform), p, 1.0);
    if (targets) {
      target.instance = spec.instance;
      target.geometry = spec.geometry;
      target.world = p;
      targets->push_back(std::move(target));
    }
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
