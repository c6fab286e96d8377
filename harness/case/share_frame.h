// R-WATERTIGHT: which triangles of a scene may share an edge or a vertex.
//
// Vulkan, Ray Traversal, Watertightness speaks of "triangles with identical
// transforms, within a single instance": within one instance, geometries
// whose transforms are bit identical (none counts as the identity, which
// moves no position) share. Across instances the specification promises
// nothing; the CTS's closedFan2 (each fan triangle in a bottom level and an
// instance of its own, every transform the identity) holds them to it all
// the same. rayspec does so only where every float evaluation of the
// transforms leaves the object ray the world ray bit for bit: an instance
// whose transform is exactly the identity (products by 1 and 0, sums with
// 0). A translated or rotated instance rounds its object ray otherwise than
// another instance does (o - T rounds; a cycle of the axes changes the
// order of a dot product's sum), so its triangles share only among
// themselves: a ray through an edge it has in common with another instance
// is a plain tie there (either triangle, both or neither), never a leak.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "case/case.h"

namespace rayspec {

// Two triangles may share an edge or vertex only where their frames are
// equal (and then by bit identical positions in that frame: their
// geometry's, transform applied).
using ShareFrame = std::array<uint32_t, 13>;

// The frame of the triangles of `geometry_transform`'s geometry under
// `instance`, the scene's instance number `index`.
ShareFrame shareFrame(const Instance& instance, uint32_t index,
                      const std::optional<Transform>& geometry_transform);

}  // namespace rayspec
