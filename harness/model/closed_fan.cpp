#include "model/closed_fan.h"

#include <bit>
#include <map>
#include <utility>

#include "case/share_frame.h"

namespace rayspec {
namespace {

// A triangle of the group: its corners (geometry transform applied), the
// edges the ray is near (WatertightHit::near_edges) and how it faces the ray.
struct FanTriangle {
  std::array<Vec3, 3> v{};
  uint8_t near = 0;
  bool front = true;
  bool degenerate = false;  // TriAmbiguity::Degenerate: a device may see no triangle
};

bool sameCorner(const Vec3& a, const Vec3& b) {
  for (int k = 0; k < 3; ++k)
    if (std::bit_cast<uint32_t>(a[k]) != std::bit_cast<uint32_t>(b[k])) return false;
  return true;
}

// How many of `tris` have the directed edge a -> b (corner k to corner k + 1).
size_t directedEdges(const std::vector<FanTriangle>& tris, const Vec3& a, const Vec3& b) {
  size_t n = 0;
  for (const FanTriangle& t : tris)
    for (int k = 0; k < 3; ++k) n += sameCorner(t.v[k], a) && sameCorner(t.v[(k + 1) % 3], b);
  return n;
}

int cornerAt(const FanTriangle& t, const Vec3& p) {
  for (int k = 0; k < 3; ++k)
    if (sameCorner(t.v[k], p)) return k;
  return -1;
}

// Three or more triangles around p, every edge at p once in each direction
// (the same winding), all facing the ray alike.
bool closedFanAround(const std::vector<FanTriangle>& tris, const Vec3& p) {
  std::vector<FanTriangle> fan;
  for (const FanTriangle& t : tris)
    if (cornerAt(t, p) >= 0) fan.push_back(t);
  if (fan.size() < 3) return false;
  for (const FanTriangle& t : fan) {
    const int k = cornerAt(t, p);
    for (const Vec3& q : {t.v[(k + 1) % 3], t.v[(k + 2) % 3]})
      if (directedEdges(fan, p, q) != 1 || directedEdges(fan, q, p) != 1) return false;
    if (t.front != fan[0].front) return false;
  }
  return true;
}

// An edge the ray is near in one triangle that another, facing alike, has
// in the opposite direction.
bool sharedEdgeNear(const std::vector<FanTriangle>& tris) {
  for (const FanTriangle& t : tris)
    for (int i = 0; i < 3; ++i) {
      if (!(t.near & (1u << i))) continue;
      const Vec3& a = t.v[(i + 1) % 3];
      const Vec3& b = t.v[(i + 2) % 3];
      for (const FanTriangle& u : tris)
        if (u.front == t.front && directedEdges({u}, b, a) > 0) return true;
    }
  return false;
}

// The vertices the ray is near: where two near edges of a triangle meet
// (edges i and j share the corner that is neither).
std::vector<Vec3> nearVertices(const std::vector<FanTriangle>& tris) {
  std::vector<Vec3> out;
  for (const FanTriangle& t : tris)
    if (std::popcount(t.near) == 2)
      for (int k = 0; k < 3; ++k)
        if (!(t.near & (1u << k))) out.push_back(t.v[k]);
  return out;
}

// A near edge that no other triangle of the group, facing alike, has in the
// opposite direction: a border, which the ray may pass beside.
bool borderEdgeNear(const std::vector<FanTriangle>& tris) {
  for (const FanTriangle& t : tris)
    for (int i = 0; i < 3; ++i) {
      if (!(t.near & (1u << i))) continue;
      bool partner = false;
      for (const FanTriangle& u : tris)
        partner = partner || (u.front == t.front &&
                              directedEdges({u}, t.v[(i + 2) % 3], t.v[(i + 1) % 3]) > 0);
      if (!partner) return true;
    }
  return false;
}

bool closes(const std::vector<FanTriangle>& tris) {
  if (tris.size() < 2) return false;
  // Nearly edge-on or within reach of all its edges (a ray nearly in the
  // plane, an error larger than the triangle): a device may see it with no
  // area (culled, R-FACE-DET) or pass outside; no longer closed either
  // where a near edge is the border.
  for (const FanTriangle& t : tris)
    if (t.degenerate) return false;
  if (borderEdgeNear(tris)) return false;
  const std::vector<Vec3> vertices = nearVertices(tris);
  if (vertices.empty()) return sharedEdgeNear(tris);
  for (const Vec3& p : vertices)
    if (closedFanAround(tris, p)) return true;
  return false;
}

}  // namespace

bool closesAroundRay(const ModelScene& scene, const std::vector<ModelCandidate>& cands,
                     const std::vector<size_t>& group, const TraceRay& ray, uint32_t flags) {
  if (group.size() < 2) return false;  // one triangle or box: its border
  std::map<ShareFrame, std::vector<FanTriangle>> by_frame;
  for (const size_t k : group) {
    const ModelCandidate& c = cands[k];
    if (c.aabb) return true;
    const ModelInstance& mi = scene.instances[c.instance];
    const ModelGeometry& g = scene.blases[mi.blas].geometries[c.geometry];
    if (c.primitive >= g.triangles.size()) return true;  // no corners kept: as before
    by_frame[shareFrame(*mi.src, c.instance, g.transform)].push_back(
        {g.triangles[c.primitive], c.near_edges, trace_detail::facing(scene, c, ray, flags).front,
         c.ambiguity == TriAmbiguity::Degenerate});
  }
  for (const auto& [frame, tris] : by_frame)
    if (closes(tris)) return true;
  return false;
}

}  // namespace rayspec
