// The `triangles: {subdivision: ...}` generator: a seeded random non-planar
// subdivision of a rectangle, split one triangle into three at a time.
#pragma once

#include <array>
#include <cstdint>

#include "base/result.h"
#include "case/case.h"

namespace rayspec {

struct SubdivisionSpec {
  uint32_t triangles = 4;  // even, at least 2: the rectangle's two, then two more a split
  std::array<double, 2> size{1, 1};
  std::array<double, 3> center{0, 0, 0};  // the corners lie in the z = center.z plane
  double relief = 0;  // each added vertex lies up to this far above that plane (non-planar)
  uint64_t seed = 1;
};

// The rectangle's corners (vertices 0..3, counter-clockwise seen from +z) as
// two triangles along the diagonal 0-2; then, until there are `triangles`,
// a triangle (a, b, c) picked at random is split at a new vertex p strictly
// inside it (random barycentric weights, each at least about 1/40; z raised
// by a random fraction of `relief`) into (a, b, p), which keeps its primitive
// index, and (b, c, p), (c, a, p) appended: every triangle stays
// counter-clockwise seen from +z, every edge but the rectangle's four sides
// is shared by exactly two triangles (the same two vertex indices), and
// every vertex but the corners is closed all around. The projection on the
// z = 0 plane tiles the rectangle, so the mesh is a height field that a ray
// along -z crosses once. A new vertex is rounded to float and kept only if
// its three triangles keep at least 1/100 of their parent's area in x and y
// and a 64th of the mean area (none near degenerate), and are each at least
// four float steps (at the rectangle's largest
// coordinate) wide, so that rounding folds nothing and a ray aimed at a face
// or an edge, its origin rounded to float, still crosses the triangles it
// is aimed at; else other weights or another triangle are drawn. An error when `triangles` is odd,
// or when the rectangle is too small for that many triangles at its coordinates (too many draws
// refused). SeededRandom and IEEE double only: the same mesh for a seed on every machine.
Result<void> makeSubdivision(const SubdivisionSpec& spec, Geometry& out);

}  // namespace rayspec
