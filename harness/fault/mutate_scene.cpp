// Case mutations of the scene: instances, facing, opacity, inactive and
// degenerate primitives as a device breaking the rule sees them.
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "base/vec3.h"
#include "case/transform.h"
#include "fault/fault_impl.h"
#include "fault/program_edit.h"

namespace rayspec {
namespace {

bool reachesTriangles(const Case& c, const Instance& inst) {
  return inst.blas && !c.scene.blases[*inst.blas].geometries.empty() &&
         c.scene.blases[*inst.blas].geometries[0].kind == Geometry::Kind::Triangles;
}

// Toggles TRIANGLE_FLIP_FACING on the triangle instances `pick` selects.
size_t toggleFlip(Case& c, const std::function<bool(const Instance&)>& pick) {
  size_t n = 0;
  for (Instance& inst : c.scene.instances)
    if (reachesTriangles(c, inst) && pick(inst)) {
      inst.flags ^= kInstanceFlipFacing;
      ++n;
    }
  return n;
}

size_t clearInstanceFlags(Case& c, uint32_t bits) {
  size_t n = 0;
  for (Instance& inst : c.scene.instances) {
    n += (inst.flags & bits) != 0;
    inst.flags &= ~bits;
  }
  return n;
}

// A triangle that holds the degenerate one (a segment P..Q or a point)
// strictly inside: base below the segment, apex above it, in the plane of the
// segment and the coordinate axis least along it (z for a point).
std::array<Vec3, 3> fattened(const std::array<DVec3, 3>& v) {
  DVec3 p = v[0], q = v[0];
  double longest = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (length(sub(v[j], v[i])) > longest) {
        longest = length(sub(v[j], v[i]));
        p = v[i];
        q = v[j];
      }
  DVec3 u = longest > 0
                ? DVec3{(q[0] - p[0]) / longest, (q[1] - p[1]) / longest, (q[2] - p[2]) / longest}
                : DVec3{1, 0, 0};
  int axis = 2;
  for (int k = 1; k >= 0; --k)
    if (std::fabs(u[k]) < std::fabs(u[axis])) axis = k;
  DVec3 n{0, 0, 0};
  n[axis] = 1;
  DVec3 w = cross(n, u);
  const double wl = length(w);
  w = {w[0] / wl, w[1] / wl, w[2] / wl};
  const double e = 0.25 * std::max(longest, 1.0);
  const DVec3 mid = axpy(p, sub(q, p), 0.5);
  return {toFloat(axpy(axpy(p, u, -e), w, -e)), toFloat(axpy(axpy(q, u, e), w, -e)),
          toFloat(axpy(mid, w, longest + e))};
}

}  // namespace

std::string instanceMaskIgnored(Case& c, ModelOptions&) {
  size_t n = 0;
  for (Instance& inst : c.scene.instances) {
    n += (inst.mask & kVisibilityMask) != kVisibilityMask;
    inst.mask = kVisibilityMask;
  }
  return describeCount(n, "instance masks set to 0xFF");
}

std::string facingInverted(Case& c, ModelOptions&) {
  return describeCount(toggleFlip(c, [](const Instance&) { return true; }),
                       "triangle instances see the other face");
}

std::string worldSpaceFacing(Case& c, ModelOptions&) {
  return describeCount(
      toggleFlip(c, [](const Instance& i) { return linearDeterminant(i.transform) < 0; }),
      "mirroring instances flip their facing");
}

std::string cullDisableIgnored(Case& c, ModelOptions&) {
  return describeCount(clearInstanceFlags(c, kInstanceFacingCullDisable),
                       "instances lose TRIANGLE_FACING_CULL_DISABLE");
}

std::string instanceOpacityIgnored(Case& c, ModelOptions&) {
  return describeCount(clearInstanceFlags(c, kInstanceForceOpaque | kInstanceForceNoOpaque),
                       "instances lose FORCE_OPAQUE / FORCE_NO_OPAQUE");
}

// Without a cull by opacity, a candidate that any-hit runs on behaves as a
// non-opaque one: every opaque source cleared.
std::string anyHitOnOpaque(Case& c, ModelOptions&) {
  if (mayUseRayFlags(c, kRayCullOpaque | kRayCullNoOpaque)) return {};
  size_t n = clearInstanceFlags(c, kInstanceForceOpaque);
  for (Blas& b : c.scene.blases)
    for (Geometry& g : b.geometries) {
      n += (g.flags & kGeometryOpaque) != 0;
      g.flags &= ~kGeometryOpaque;
    }
  n += clearRayFlags(c, kRayOpaque);
  return describeCount(n, "opaque geometries, instances or ray flags made any-hit candidates");
}

std::string instanceTransformInverted(Case& c, ModelOptions&) {
  size_t n = 0;
  for (Instance& inst : c.scene.instances) {
    if (inst.transform == kIdentity) continue;
    const DTransform inv = invertTransform(inst.transform);
    Transform t;
    for (int k = 0; k < 12; ++k) t[k] = static_cast<float>(inv[k]);
    if (t == inst.transform) continue;  // its own inverse (a mirror)
    inst.transform = t;
    ++n;
  }
  return describeCount(n, "instance transforms replaced by their inverses");
}

std::string inactiveRevived(Case& c, ModelOptions&) {
  size_t n = 0;
  for (Blas& b : c.scene.blases)
    for (Geometry& g : b.geometries) {
      for (Vec3& v : g.vertices)
        if (std::isnan(v[0])) {
          v[0] = 0;
          ++n;
        }
      for (auto& a : g.aabbs)
        if (std::isnan(a[0])) {
          a[0] = a[3] - std::max(a[4] - a[1], 1.0f);
          ++n;
        }
    }
  for (Instance& inst : c.scene.instances)
    if (!inst.blas && !c.scene.blases.empty()) {
      inst.blas = 0;
      ++n;
    }
  return describeCount(n, "inactive vertices, boxes or instances made active");
}

// Mesa 26.2.6's lavapipe: the BVH builder leaves each leaf in the slot of its
// index and counts the active ones, and the encoder converts only the first
// active-count slots: with k inactive objects of n, an active one at index
// n - k or later is lost. Instances with mask 0x00 count as inactive there.
namespace {

// Makes inactive the active items at index n - k or later (k = the inactive
// ones); returns how many.
size_t hideLastActive(size_t items, const std::function<bool(size_t)>& inactive,
                      const std::function<void(size_t)>& deactivate) {
  size_t k = 0;
  for (size_t i = 0; i < items; ++i) k += inactive(i);
  size_t n = 0;
  for (size_t i = items - k; i < items; ++i)
    if (!inactive(i)) {
      deactivate(i);
      ++n;
    }
  return n;
}

size_t hideLastActivePrimitives(Geometry& g) {
  if (g.kind == Geometry::Kind::Aabbs)
    return hideLastActive(
        g.aabbs.size(), [&](size_t i) { return std::isnan(g.aabbs[i][0]); },
        [&](size_t i) { g.aabbs[i][0] = std::nanf(""); });
  if (!g.indices.empty()) return 0;  // a vertex may be shared: left alone
  auto nan_x = [&](size_t p) {
    for (size_t k = 0; k < 3; ++k)
      if (std::isnan(g.vertices[p * 3 + k][0])) return true;
    return false;
  };
  return hideLastActive(g.vertices.size() / 3, nan_x,
                        [&](size_t p) { g.vertices[p * 3][0] = std::nanf(""); });
}

}  // namespace

std::string inactiveHidesLastActive(Case& c, ModelOptions&) {
  std::vector<Instance>& inst = c.scene.instances;
  size_t n = hideLastActive(
      inst.size(), [&](size_t i) { return !inst[i].blas || (inst[i].mask & kVisibilityMask) == 0; },
      [&](size_t i) { inst[i].blas.reset(); });
  for (Blas& b : c.scene.blases)
    for (Geometry& g : b.geometries) n += hideLastActivePrimitives(g);
  return describeCount(n, "active instances or primitives after inactive ones made inactive");
}

std::optional<std::array<DVec3, 3>> degenerateTriangle(const Geometry& g, uint32_t p) {
  std::array<DVec3, 3> v;
  for (uint32_t k = 0; k < 3; ++k) {
    const uint32_t i = g.indices.empty() ? p * 3 + k : g.indices[p * 3 + k];
    if (i >= g.vertices.size()) return std::nullopt;
    v[k] = {g.vertices[i][0], g.vertices[i][1], g.vertices[i][2]};
    for (double x : v[k])
      if (!std::isfinite(x)) return std::nullopt;
  }
  if (length(cross(sub(v[1], v[0]), sub(v[2], v[0]))) != 0) return std::nullopt;
  return v;
}

void setTriangle(Geometry& g, uint32_t p, const std::array<Vec3, 3>& t) {
  for (uint32_t k = 0; k < 3; ++k) {
    if (g.indices.empty()) {
      g.vertices[p * 3 + k] = t[k];
    } else {  // its own vertices: others may share the old ones
      g.indices[p * 3 + k] = static_cast<uint32_t>(g.vertices.size());
      g.vertices.push_back(t[k]);
    }
  }
}

std::string degenerateHit(Case& c, ModelOptions&) {
  size_t n = 0;
  for (Blas& b : c.scene.blases)
    for (Geometry& g : b.geometries) {
      if (g.kind != Geometry::Kind::Triangles) continue;
      for (uint32_t p = 0; p < g.primitiveCount(); ++p)
        if (const auto v = degenerateTriangle(g, p)) {
          setTriangle(g, p, fattened(*v));
          ++n;
        }
    }
  return describeCount(n, "degenerate triangles made hittable");
}

}  // namespace rayspec
