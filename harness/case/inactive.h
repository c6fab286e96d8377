// R-INACTIVE: which primitives a build or update treats as inactive
// (Vulkan, "Inactive Primitives and Instances"): a triangle with NaN in the X
// component of any vertex, a box whose minimum X is NaN, an instance with a
// null reference. An update may not change which primitives are inactive
// (VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-03663, -03664).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "base/vec3.h"
#include "case/case.h"

namespace rayspec {

// NaN in the X component of any vertex (as given, before a geometry transform).
inline bool triangleInactive(const std::array<Vec3, 3>& tri) {
  return std::isnan(tri[0][0]) || std::isnan(tri[1][0]) || std::isnan(tri[2][0]);
}

// Primitive p of g (a triangle through its indices, or a box) is inactive.
// A triangle whose index lies past the vertices counts as active (the
// parser reports that index on its own).
inline bool primitiveInactive(const Geometry& g, uint32_t p) {
  if (g.kind == Geometry::Kind::Aabbs) return std::isnan(g.aabbs[p][0]);
  std::array<Vec3, 3> tri{};
  for (uint32_t k = 0; k < 3; ++k) {
    const size_t i = g.indices.empty() ? size_t{p} * 3 + k : g.indices[size_t{p} * 3 + k];
    if (i >= g.vertices.size()) return false;
    tri[k] = g.vertices[i];
  }
  return triangleInactive(tri);
}

}  // namespace rayspec
