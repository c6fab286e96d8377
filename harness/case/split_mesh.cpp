// scene.split (case/split_mesh.h).
#include "case/split_mesh.h"

#include <cmath>
#include <string>

namespace rayspec {
namespace {

// The triangle k's three vertices, non-indexed.
std::vector<Vec3> triangleOf(const Geometry& g, uint32_t k) {
  std::vector<Vec3> out;
  for (uint32_t v = 0; v < 3; ++v)
    out.push_back(g.vertices[g.indices.empty() ? 3 * k + v : g.indices[3 * k + v]]);
  return out;
}

Geometry oneTriangle(const Geometry& g, std::vector<Vec3> vertices) {
  Geometry t;
  t.kind = Geometry::Kind::Triangles;
  t.flags = g.flags;
  t.transform = g.transform;
  t.vertices = std::move(vertices);
  t.loc = g.loc;
  return t;
}

Result<void> checkSplittable(const Scene& scene, const SplitSpec& spec) {
  if (spec.blas >= scene.blases.size())
    return errorOf(ErrorKind::Input, "scene.split: no such BLAS");
  const Blas& b = scene.blases[spec.blas];
  if (b.geometries.size() != 1 || b.geometries[0].kind != Geometry::Kind::Triangles)
    return errorOf(ErrorKind::Input,
                   "scene.split: BLAS '" + b.name + "' must hold one triangle geometry");
  const Geometry& g = b.geometries[0];
  if (g.vertex_format != VertexFormat::Float3 || g.index16)
    return errorOf(ErrorKind::Input,
                   "scene.split: BLAS '" + b.name + "' must have float3 vertices");
  if (g.primitiveCount() == 0)
    return errorOf(ErrorKind::Input, "scene.split: BLAS '" + b.name + "' has no triangle");
  return {};
}

// The object position whose image under `m` (a translation after a cycle of
// the axes) is `world`, exactly; empty where float cannot hold it.
std::optional<Vec3> objectOf(const Transform& m, const Vec3& world) {
  Vec3 object{};
  for (int row = 0; row < 3; ++row) {
    const double moved = double(world[row]) - double(m[4 * row + 3]);
    for (int col = 0; col < 3; ++col)
      if (m[4 * row + col] != 0) object[col] = static_cast<float>(moved);
    if (double(static_cast<float>(moved)) != moved) return std::nullopt;
  }
  return object;
}

Result<void> splitIntoInstances(Scene& scene, const SplitSpec& spec) {
  const Geometry g = scene.blases[spec.blas].geometries[0];
  if (g.transform)
    return errorOf(ErrorKind::Input, "scene.split: into instances needs no geometry transform");
  const std::string name = scene.blases[spec.blas].name;
  const uint32_t n = g.primitiveCount();
  std::vector<uint32_t> blas_of(n);
  for (uint32_t k = 0; k < n; ++k) {
    std::vector<Vec3> object;
    for (const Vec3& w : triangleOf(g, k)) {
      const std::optional<Vec3> o = objectOf(splitTransform(spec, k), w);
      if (!o)
        return errorOf(ErrorKind::Input,
                       "scene.split: instance " + std::to_string(k) +
                           "'s translation moves a vertex of triangle " + std::to_string(k) +
                           " off the float grid (choose a translation that keeps it exact)");
      object.push_back(*o);
    }
    Blas b{name + "#" + std::to_string(k), {oneTriangle(g, std::move(object))}, {}};
    blas_of[k] = k == 0 ? spec.blas : static_cast<uint32_t>(scene.blases.size());
    if (k == 0)
      scene.blases[spec.blas] = std::move(b);
    else
      scene.blases.push_back(std::move(b));
  }
  std::vector<Instance> out;
  for (const Instance& inst : scene.instances) {
    if (inst.blas != spec.blas) {
      out.push_back(inst);
      continue;
    }
    if (inst.transform != kIdentity)
      return errorOf(ErrorKind::Input,
                     "scene.split: an instance of '" + name + "' has a transform");
    for (uint32_t k = 0; k < n; ++k) {
      Instance piece = inst;
      piece.blas = blas_of[k];
      piece.transform = splitTransform(spec, k);
      out.push_back(piece);
    }
  }
  if (out.size() > kMaxInstances)
    return errorOf(ErrorKind::Input, "scene.split: more than 2^20 instances");
  scene.instances = std::move(out);
  return {};
}

}  // namespace

Transform splitTransform(const SplitSpec& spec, uint32_t k) {
  Transform m{};
  const uint32_t shift = spec.cycle_axes ? k % 3 : 0;
  for (uint32_t row = 0; row < 3; ++row) {
    m[4 * row + (row + 3 - shift) % 3] = 1;  // world axis row takes object axis row - shift
    m[4 * row + 3] = (k % 2) ? spec.translate[row] : 0.0f;
  }
  return m;
}

Result<void> splitMesh(Scene& scene, const SplitSpec& spec) {
  RAYSPEC_TRY_VOID(checkSplittable(scene, spec));
  if (!scene.earlier.empty())
    return errorOf(ErrorKind::Input, "scene.split: not with scene.update");
  if (spec.into == SplitSpec::Into::Instances) return splitIntoInstances(scene, spec);
  Blas& b = scene.blases[spec.blas];
  const Geometry g = b.geometries[0];
  b.geometries.clear();
  for (uint32_t k = 0; k < g.primitiveCount(); ++k)
    b.geometries.push_back(oneTriangle(g, triangleOf(g, k)));
  return {};
}

}  // namespace rayspec
