// Rays aimed at what the generated scene holds (as the last update left
// it): a triangle's centroid, a point on one of its edges or a vertex, a
// box's centre, a face centre, an edge or a corner, through the geometry
// and instance transforms (double), so most rays hit something and those
// at edges and vertices meet the ambiguity rules. Now and then a grazing
// ray (in the triangle's plane, along the box's face) or one from far away
// (huge coordinates), only where no active instance holds boxes. And the
// case format's own `aim` form (rays.aim) over a triangle instance.
#include <cmath>

#include "case/huge_rays.h"
#include "fuzz/case_generator.h"

namespace rayspec {
namespace {

// A point of one primitive in object space, and a direction along the
// primitive's surface through it (for a grazing ray).
struct ObjectPoint {
  DVec3 at{}, along{};
  std::string feature;
};

bool anyNan(const DVec3& v) {
  return std::isnan(v[0]) || std::isnan(v[1]) || std::isnan(v[2]);
}

DVec3 lerp(const DVec3& a, const DVec3& b, double f) {
  return axpy(a, sub(b, a), f);
}

std::string vec(const DVec3& v) {
  return "[" + CaseGenerator::num(float(v[0])) + ", " + CaseGenerator::num(float(v[1])) + ", " +
         CaseGenerator::num(float(v[2])) + "]";
}

}  // namespace

std::optional<std::string> CaseGenerator::aimedRay() {
  std::vector<size_t> active;
  for (size_t i = 0; i < instances_.size(); ++i)
    if (instances_[i]) active.push_back(i);
  if (active.empty()) return std::nullopt;
  const Placed& inst = *instances_[oneOf(active)];
  const Geometry& g = oneOf(blas_[inst.blas].data);
  const uint32_t primitives = g.primitiveCount();
  if (!primitives) return std::nullopt;
  const uint32_t p = uint32_t(pick(primitives));
  ObjectPoint o;
  if (g.kind == Geometry::Kind::Aabbs) {
    const auto& b = g.aabbs[p];
    if (std::isnan(b[0])) return std::nullopt;
    // Each axis at the box's minimum, middle or maximum: as many axes at an
    // end as the feature has (0 centre, 1 face, 2 edge, 3 corner).
    const uint64_t ends = pick(4);
    const uint64_t first = pick(3);
    int flat = -1;
    for (int k = 0; k < 3; ++k) {
      const bool end = (k - int(first) + 3) % 3 < int(ends);
      o.at[k] = end ? (chance(0.5) ? b[k] : b[3 + k]) : (b[k] + b[3 + k]) / 2;
      if (end && flat < 0) flat = k;
    }
    o.along[(flat < 0 ? 0 : flat + 1) % 3] = 1;
    o.feature = ends == 0 ? "aimed-box-centre" : "aimed-box-boundary";
  } else {
    DVec3 v[3];
    for (int k = 0; k < 3; ++k) {
      const uint32_t i = g.indices.empty() ? 3 * p + k : g.indices[3 * p + k];
      v[k] = toDouble(g.vertices[i]);
      if (anyNan(v[k])) return std::nullopt;
    }
    const uint64_t kind = pick(10), e = pick(3);
    if (kind < 5) {
      o.at = scaled(axpy(axpy(v[0], v[1], 1), v[2], 1), 1.0 / 3);
      o.feature = "aimed-centre";
    } else if (kind < 8) {
      o.at = lerp(v[e], v[(e + 1) % 3], oneOf<double>({0.5, 0.25, 0.75, 0.125}));
      o.feature = "aimed-edge";
    } else {
      o.at = v[e];
      o.feature = "aimed-vertex";
    }
    o.along = sub(v[(e + 2) % 3], o.at);
    if (length(o.along) == 0) o.along = sub(v[(e + 1) % 3], v[e]);
  }
  return aimedText(inst, g, o.at, o.along, o.feature);
}

// The ray at `at` (object space of `g` in `inst`): from a point around it
// (far away now and then), or grazing along `along`.
std::string CaseGenerator::aimedText(const Placed& inst, const Geometry& g, DVec3 at, DVec3 along,
                                     const std::string& feature) {
  features_.insert(feature);
  if (g.transform) {
    at = applyAffine(toDouble(*g.transform), at, 1);
    along = applyAffine(toDouble(*g.transform), along, 0);
  }
  const DTransform m = toDouble(inst.transform);
  at = applyAffine(m, at, 1);
  along = applyAffine(m, along, 0);
  if (chance(0.06) && length(along) > 0) {
    features_.insert("grazing-ray");
    return "{origin: " + vec(axpy(at, along, -2)) + ", direction: " + vec(along);
  }
  DVec3 d{eighths(-1, 1), eighths(-1, 1), eighths(-1, 1)};
  if (length(d) < 0.25) d[2] = chance(0.5) ? 1 : -1;
  double reach = eighths(2, 6);
  // Not where boxes are: every box's programs test the sphere inscribed in
  // it (sphere_hit, sphere_near, sphere_far), and a huge ray at such a box
  // has no legal set to judge it by (case/huge_rays.h, the definition the
  // portability check refuses a case by). The draw stays, so that the other
  // cases' sequences do not move.
  if (chance(0.05) && !activeBoxes()) {
    features_.insert("huge-ray");
    reach = double(1 + pick(100)) * kHugeRayReach;
  }
  // The point at t = 1.
  return "{origin: " + vec(axpy(at, d, reach)) + ", direction: " + vec(scaled(d, -reach));
}

// Whether an active instance (as the last update left them) holds boxes.
bool CaseGenerator::activeBoxes() const {
  for (const auto& inst : instances_)
    if (inst && blas_[inst->blas].aabbs) return true;
  return false;
}

// rays.aim over a triangle geometry of an active instance: its vertices
// closed all around, points on its shared edges, its centroids.
std::string CaseGenerator::aimForm() {
  std::vector<std::pair<size_t, size_t>> meshes;  // instance, geometry
  for (size_t i = 0; i < instances_.size(); ++i)
    if (instances_[i] && !blas_[instances_[i]->blas].aabbs)
      for (size_t k = 0; k < blas_[instances_[i]->blas].data.size(); ++k)
        if (blas_[instances_[i]->blas].shaped[k]) meshes.push_back({i, k});
  if (meshes.empty()) return "";
  features_.insert("aim-form");
  const auto [instance, geometry] = oneOf(meshes);
  // Faces always: every mesh has a centroid (a one-cell grid has no closed vertex).
  std::string at;
  for (const char* f : {"vertices", "edges"})
    if (chance(0.7)) at += std::string(f) + ", ";
  const DVec3 offset{eighths(-1, 1), eighths(-1, 1), (chance(0.5) ? 1 : -1) * eighths(1, 3)};
  return "  aim: {instance: " + std::to_string(instance) +
         ", geometry: " + std::to_string(geometry) + ", at: [" + at +
         "faces], edge_points: " + std::to_string(1 + pick(3)) + ", offset: " + vec(offset) +
         ", direction_scale: " + num(oneOf<double>({1, 0.5, 2})) + "}\n";
}

}  // namespace rayspec
