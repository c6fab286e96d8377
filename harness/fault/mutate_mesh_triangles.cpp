// R-AS-SIZE broken on a triangle mesh: a build that loses one triangle of a
// mesh (its primitive index kept, as an inactive one keeps it) or that keeps
// one twice (the copy appended as a primitive of its own), as a device whose
// build drops or duplicates a leaf. The middle triangle of the first mesh of
// 4 to 65,536 triangles in float3 vertices, or of a mesh split into as many
// one-triangle geometries or instances (scene.split): one a watertight mesh
// needs.
// Larger meshes (accel/size-triangles) are left to build-counts-16-bit: each
// planted fault runs the model again on the whole case, 12 s at 2^20.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "fault/fault_impl.h"

namespace rayspec {
namespace {

// The first geometry of a BLAS some instance uses that is a mesh of 4 to
// 2^16 float3 triangles; null when none is.
Geometry* firstMesh(Case& c) {
  if (c.scene.updates()) return nullptr;
  for (const Instance& inst : c.scene.instances) {
    if (!inst.blas) continue;
    for (Geometry& g : c.scene.blases[*inst.blas].geometries)
      if (g.kind == Geometry::Kind::Triangles && g.primitiveCount() >= 4 &&
          g.primitiveCount() <= (1u << 16) && g.vertex_format == VertexFormat::Float3 &&
          g.written.empty())
        return &g;
  }
  return nullptr;
}

std::array<Vec3, 3> corners(const Geometry& g, uint32_t p) {
  std::array<Vec3, 3> t;
  for (uint32_t v = 0; v < 3; ++v)
    t[v] = g.vertices[g.indices.empty() ? 3 * p + v : g.indices[3 * p + v]];
  return t;
}

// A mesh split into pieces (scene.split): the geometries of one triangle
// each, in instance then geometry order, of the active instances; the
// middle of them where there are 4 to 2^16.
Geometry* middlePiece(Case& c) {
  if (c.scene.updates()) return nullptr;
  std::vector<Geometry*> pieces;
  for (const Instance& inst : c.scene.instances) {
    if (!inst.blas) continue;
    for (Geometry& g : c.scene.blases[*inst.blas].geometries)
      if (g.kind == Geometry::Kind::Triangles && g.primitiveCount() == 1 &&
          g.vertex_format == VertexFormat::Float3 && g.written.empty())
        pieces.push_back(&g);
  }
  if (pieces.size() < 4 || pieces.size() > (1u << 16)) return nullptr;
  return pieces[pieces.size() / 2];
}

// The triangle the two faults lose or keep twice: the middle one of the
// first mesh, else the middle piece of a split mesh; its primitive index.
Geometry* victim(Case& c, uint32_t* p, std::string* what) {
  if (Geometry* g = firstMesh(c)) {
    *p = g->primitiveCount() / 2;
    *what = "triangle " + std::to_string(*p) + " of the first mesh";
    return g;
  }
  *p = 0;
  *what = "the middle triangle of a mesh split into geometries or instances";
  return middlePiece(c);
}

}  // namespace

std::string meshTriangleDropped(Case& c, ModelOptions&) {
  uint32_t p = 0;
  std::string what;
  Geometry* g = victim(c, &p, &what);
  if (!g) return "";
  const float nan = std::numeric_limits<float>::quiet_NaN();
  if (g->indices.empty()) {
    for (uint32_t v = 0; v < 3; ++v) g->vertices[3 * p + v] = {nan, nan, nan};
  } else {
    const auto lost = static_cast<uint32_t>(g->vertices.size());
    g->vertices.push_back({nan, nan, nan});
    for (uint32_t v = 0; v < 3; ++v) g->indices[3 * p + v] = lost;
  }
  return what + " lost by the build";
}

std::string meshTriangleDuplicated(Case& c, ModelOptions&) {
  uint32_t p = 0;
  std::string what;
  Geometry* g = victim(c, &p, &what);
  if (!g) return "";
  const uint32_t copy = g->primitiveCount();
  if (g->indices.empty()) {
    const std::array<Vec3, 3> t = corners(*g, p);
    g->vertices.insert(g->vertices.end(), t.begin(), t.end());
  } else {
    for (uint32_t v = 0; v < 3; ++v) g->indices.push_back(g->indices[3 * p + v]);
  }
  return what + " kept twice by the build (again as primitive " + std::to_string(copy) + ")";
}

}  // namespace rayspec
