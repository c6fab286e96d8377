#include "compare/shared_edge.h"

#include <array>
#include <map>
#include <tuple>

#include "case/share_frame.h"

namespace rayspec {
namespace {

using Pos = std::tuple<float, float, float>;
using Tri = std::array<Pos, 3>;

bool triangleOf(const Case& c, const Candidate& k, Tri* out) {
  if (k.instance >= c.scene.instances.size() || !c.scene.instances[k.instance].blas) return false;
  const Blas& b = c.scene.blases[*c.scene.instances[k.instance].blas];
  if (k.geometry >= b.geometries.size()) return false;
  const Geometry& g = b.geometries[k.geometry];
  if (g.kind != Geometry::Kind::Triangles || k.primitive >= g.primitiveCount()) return false;
  for (uint32_t v = 0; v < 3; ++v) {
    const uint32_t i = g.indices.empty() ? k.primitive * 3 + v : g.indices[k.primitive * 3 + v];
    if (i >= g.vertices.size()) return false;
    const Vec3& p = g.vertices[i];
    (*out)[v] = {p[0], p[1], p[2]};
  }
  return true;
}

using Groups = std::map<ShareFrame, std::vector<Tri>>;

// The frame candidate k's triangle shares edges in (triangleOf checked it).
ShareFrame frameOf(const Case& c, const Candidate& k) {
  const Instance& inst = c.scene.instances[k.instance];
  return shareFrame(inst, k.instance, c.scene.blases[*inst.blas].geometries[k.geometry].transform);
}

// The hit candidates' triangles, grouped by frame (case/share_frame.h);
// false when some candidate is not a triangle of the case.
bool groupTriangles(const Case& c, const RayAmbiguity& a, Groups* groups) {
  for (const Candidate& k : a.candidates) {
    Tri t;
    if (!k.hit) continue;
    if (!triangleOf(c, k, &t)) return false;
    (*groups)[frameOf(c, k)].push_back(t);
  }
  return true;
}

}  // namespace

bool crossesBorderOnly(const Case& c, const RayAmbiguity& a) {
  Groups groups;
  if (!groupTriangles(c, a, &groups) || groups.size() != 1 || crossesSharedEdge(c, a)) return false;
  const std::vector<Tri>& tris = groups.begin()->second;
  if (a.reason == AmbiguityReason::Edge) return tris.size() == 1;
  if (a.reason != AmbiguityReason::Vertex) return false;
  std::map<Pos, size_t> vertex_use;
  for (const Tri& t : tris)
    for (const Pos& p : t) ++vertex_use[p];
  for (const auto& [p, n] : vertex_use)
    if (n == tris.size()) return true;  // a vertex of every candidate, its fan open
  return false;
}

bool crossesSharedEdge(const Case& c, const RayAmbiguity& a) {
  if (a.reason != AmbiguityReason::Edge && a.reason != AmbiguityReason::Vertex) return false;
  // Group the hit candidates by frame (case/share_frame.h).
  Groups groups;
  for (const Candidate& k : a.candidates) {
    Tri t;
    if (k.hit && triangleOf(c, k, &t)) groups[frameOf(c, k)].push_back(t);
  }
  for (const auto& [key, tris] : groups) {
    // Directed edges, corner k to corner k + 1: two triangles of the same
    // winding meet their shared edge in opposite directions (one triangle
    // twice, in both windings, too: the model tells such a fold by facing).
    std::map<std::pair<Pos, Pos>, int> directed;
    for (const Tri& t : tris)
      for (int e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
    auto count = [&](const Pos& from, const Pos& to) {
      const auto it = directed.find({from, to});
      return it == directed.end() ? 0 : it->second;
    };
    if (a.reason == AmbiguityReason::Edge) {
      for (const auto& [e, n] : directed)
        if (count(e.second, e.first) > 0) return true;
      continue;
    }
    // A vertex every candidate shares, closed when each of its edges is
    // shared, once in each direction.
    std::map<Pos, int> vertex_use;
    for (const Tri& t : tris)
      for (const Pos& p : t) ++vertex_use[p];
    for (const auto& [p, n] : vertex_use) {
      if (n < 3) continue;  // a closed fan has at least 3 triangles
      bool closed = true;
      for (const auto& [e, m] : directed)
        if ((e.first == p || e.second == p) && (m != 1 || count(e.second, e.first) != 1))
          closed = false;
      if (closed) return true;
    }
  }
  return false;
}

SharedCrossing sharedCrossing(const Case& c, const RayAmbiguity& a) {
  SharedCrossing s;
  RayAmbiguity shared{a.ray, a.reason, a.shared_triangles, {}};
  for (Candidate& k : shared.candidates) {
    s.model_hits += k.hit ? 1 : 0;
    k.hit = true;
  }
  if (shared.candidates.size() < 2 || s.model_hits == 0 || !crossesSharedEdge(c, shared)) return {};
  s.triangles = static_cast<uint32_t>(shared.candidates.size());
  return s;
}

SharedCrossing anyHitCrossing(const Case& c, const RayAmbiguity& a, uint32_t model_any_hit_runs) {
  const SharedCrossing s = sharedCrossing(c, a);
  return model_any_hit_runs >= s.model_hits ? s : SharedCrossing{};
}

}  // namespace rayspec
