// The exact tier's candidate boxes (model/box_pad.h): every triangle the
// exact test keeps for a ray (a hit, or a miss within the error bound) lies
// in a box the ray crosses, on every launch ray of every hard case (cases/
// precision, watertight, stability: vertex-, edge- and face-aimed rays at
// magnitudes up to 1e6, through identity, translated, swapped and rotated
// instances); and the pads are far tighter than the former 1e-5 of the
// coordinates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "library/case_discovery.h"
#include "model/box_pad.h"
#include "model/frame_error.h"
#include "model/model_scene.h"
#include "model/watertight.h"
#include "model_support.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

constexpr double kU = 5.9604644775390625e-08;  // 2^-24

DVec3 toObject(const std::array<double, 12>& m, const Vec3& v, double w) {
  DVec3 r;
  for (int k = 0; k < 3; ++k)
    r[k] = m[k * 4] * v[0] + m[k * 4 + 1] * v[1] + m[k * 4 + 2] * v[2] + m[k * 4 + 3] * w;
  return r;
}

// Does the ray o + t d, t >= 0, cross the box [lo, hi]?
bool crosses(const DVec3& o, const DVec3& d, const DVec3& lo, const DVec3& hi) {
  double t0 = 0, t1 = INFINITY;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) {
      if (o[k] < lo[k] || o[k] > hi[k]) return false;
      continue;
    }
    double a = (lo[k] - o[k]) / d[k], b = (hi[k] - o[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1;
}

// What the kept pairs (triangle, launch ray) came to: each checked (in a box
// the ray crosses), or outside the argument (box_pad.cpp) as a sliver or a
// far degenerate (checkPair).
struct PairCounts {
  size_t kept = 0, checked = 0, sliver = 0, far = 0;
};

// The triangle's box padded as ownTriangleBounds pads it, and grown by the
// triangle's own size besides (far).
struct PaddedBoxes {
  DVec3 lo, hi, far_lo, far_hi;
};

PaddedBoxes paddedBoxes(const ModelGeometry& g, const DVec3 (&v)[3]) {
  PaddedBoxes b;
  double size = 0;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = std::min({v[0][k], v[1][k], v[2][k]});
    b.hi[k] = std::max({v[0][k], v[1][k], v[2][k]});
    size = std::max(size, b.hi[k] - b.lo[k]);
  }
  for (int k = 0; k < 3; ++k) {
    const double m = std::max(std::fabs(b.lo[k]), std::fabs(b.hi[k]));
    const double pad = kBoxMagnitudeSteps * kU * m + g.ray_pad + 4 * g.vertex_err[k];
    b.far_lo[k] = b.lo[k] - pad - size;
    b.far_hi[k] = b.hi[k] + pad + size;
    b.lo[k] -= pad;
    b.hi[k] += pad;
  }
  return b;
}

// A kept pair whose padded box the ray misses lies outside the argument
// (box_pad.cpp) where the test calls the triangle degenerate and the ray
// misses it (a hit, an edge or a vertex is always held), as
//  - a sliver: its determinant within its bound while the ray lies outside
//    some edge's zone (not all three edges near). The bound grows with the
//    ray's distance from the triangle (the edge functions' rounding, with
//    the products |p_a| |p_b|) and never shrinks, while a thin triangle's
//    determinant is its length times its width: every ray farther than
//    about its width over the rounding calls it degenerate, however far it
//    passes from its edges, so no pad holds them (watertight/
//    subdivision-large's random splits: some 360,000 pairs, most of them
//    also farther than the triangle's size);
//  - far: else, a ray farther from it than its own size (its rounding
//    exceeds it); the former pads left those out too.
// Else the pair is checked: the ray crosses the padded box.
void checkPair(const WatertightHit& h, const DVec3& o, const DVec3& d, const PaddedBoxes& b,
               const std::string& name, size_t primitive, double pad, PairCounts& n) {
  ++n.kept;
  if (!crosses(o, d, b.lo, b.hi) && h.ambiguity == TriAmbiguity::Degenerate && !h.hit) {
    if (h.near_edges != 0b111) {
      ++n.sliver;
      return;
    }
    if (!crosses(o, d, b.far_lo, b.far_hi)) {
      ++n.far;
      return;
    }
  }
  ++n.checked;
  ASSERT_TRUE(crosses(o, d, b.lo, b.hi))
      << name << " primitive " << primitive << " pad " << pad << " hit " << h.hit << " ambiguity "
      << int(h.ambiguity) << " near edges " << int(h.near_edges);
}

// Every triangle of geometry g the exact test keeps for one launch ray
// through instance mi (a hit, or a miss within the error bound, in Embree's
// interval), each pair checked.
void checkRay(const ModelInstance& mi, const ModelGeometry& g, const Ray& r,
              const std::string& name, PairCounts& n) {
  const DVec3 o = toObject(mi.inverse, r.origin, 1), d = toObject(mi.inverse, r.direction, 0);
  FrameError err;
  objectRayFrameError(mi.form, mi.inverse, mi.inverse_f, {r.origin[0], r.origin[1], r.origin[2]},
                      {r.direction[0], r.direction[1], r.direction[2]}, err);
  err.vertex = g.vertex_err;
  for (size_t p = 0; p < g.triangles.size(); ++p) {
    const auto& tri = g.triangles[p];
    const DVec3 v[3] = {{tri[0][0], tri[0][1], tri[0][2]},
                        {tri[1][0], tri[1][1], tri[1][2]},
                        {tri[2][0], tri[2][1], tri[2][2]}};
    const WatertightHit h = watertightIntersect(o, d, v[0], v[1], v[2], err);
    if (!h.valid || (!h.hit && h.ambiguity == TriAmbiguity::None)) continue;
    if (h.t < r.tmin * (1 - 1e-5) || h.t > r.tmax * (1 + 1e-5)) continue;  // Embree's interval
    checkPair(h, o, d, paddedBoxes(g, v), name, p, g.ray_pad, n);
  }
}

TEST(BoxPad, EveryKeptTriangleLiesInABoxTheRayCrosses) {
  const std::string dir = RAYSPEC_SOURCE_DIR "/cases";
  size_t cases = 0;
  PairCounts n;
  for (const char* family : {"precision/*", "watertight/*", "stability/*"})
    for (const CaseFile& f : findCases(dir, family)) {
      ParseResult p = loadCase(f, dir);
      if (!p.value || !p.errors.empty()) continue;
      const Case& c = *p.value;
      ModelScene s;
      ASSERT_TRUE(buildModelScene(s, c, ModelTier::Exact, true).ok());
      ++cases;
      for (const ModelInstance& mi : s.instances) {
        if (mi.blas < 0) continue;
        for (const ModelGeometry& g : s.blases[mi.blas].geometries) {
          if (g.kind != Geometry::Kind::Triangles) continue;
          for (const Ray& r : c.rays.rays) ASSERT_NO_FATAL_FAILURE(checkRay(mi, g, r, f.name, n));
        }
      }
    }
  std::printf("BoxPad: %zu cases, %zu pairs kept: %zu checked, %zu slivers, %zu far\n", cases,
              n.kept, n.checked, n.sliver, n.far);
  EXPECT_GT(cases, 50u);
  EXPECT_GT(n.checked, 10000u);
  EXPECT_LT(n.far, n.checked / 1000);
}

// A grid of unit cells at 1e5 seen from 3 units away: the pad is a small
// fraction of a cell (the former pad was 1e-5 of the coordinates: 1.0, a
// whole cell); through an instance translated by 1e6 it still covers a
// device's origin error (2 float steps of the translation) and stays below
// the former 1e-5 of the translation.
// A 4x4 grid of unit cells centred at CENTER in its BLAS, placed by the
// instance line INSTANCE, seen straight down from 3 units above ORIGIN.
Case gridSeenFromAbove(const std::string& center, const std::string& instance,
                       const std::string& origin) {
  return model_test::parseInline(R"(
rules: [R-PREC]
scene:
  blas:
    mesh:
      - triangles: {grid: {cells: [4, 4], size: [4, 4], center: [)" +
                                 center + R"(]}}
  instances:
    - )" + instance + R"(
rays:
  grid: {size: [17, 17], origin: [)" +
                                 origin +
                                 R"(, 3], du: [0.25, 0, 0], dv: [0, 0.25, 0], direction: [0, 0, -1]}
pipeline:
  miss:
    - [count: miss]
  hit_groups:
    - closest_hit: [count: closesthit]
outputs:
  counters: [miss, closesthit]
)");
}

TEST(BoxPad, TighterThanTheFormerPads) {
  const Case far = gridSeenFromAbove("100002, 100002, 0", "{blas: mesh}", "100000, 100000");
  const std::vector<double> pads = blasRayPads(far);
  ASSERT_EQ(pads.size(), 1u);
  EXPECT_GT(pads[0], 128 * kU * 3);  // the zone, at least 3 units away
  EXPECT_LT(pads[0], 1e-2);
  const Case moved = gridSeenFromAbove(
      "2, 2, 0", "{blas: mesh, transform: {translate: [1000000, 1000000, 0]}}", "1000000, 1000000");
  const double pad = blasRayPads(moved)[0];
  EXPECT_GT(pad, 2 * 2 * kU * 1e6);
  EXPECT_LT(pad, 1e-5 * 1e6 / 2);
}

// Many instances times many origins (accel/size-instances: 2^32 pairs, 40 s
// exactly): the origins' bounding box corners stand in for them, and the
// pads never shrink.
TEST(BoxPad, TheOriginsBoxNeverShrinksAPad) {
  for (const char* name : {"precision/huge-translations", "precision/vertex-and-edge-aim"}) {
    const std::optional<CaseFile> f = suiteCase(name);
    ASSERT_TRUE(f) << name;
    const ParseResult p = loadSuiteCase(*f);
    ASSERT_TRUE(p.value) << name;
    const Case& c = *p.value;
    const std::vector<double> hull = blasRayPads(c, 0), exact = blasRayPads(c, 1e300);
    ASSERT_EQ(hull.size(), exact.size());
    for (size_t b = 0; b < hull.size(); ++b) EXPECT_GE(hull[b], exact[b]) << name;
  }
}

}  // namespace
}  // namespace rayspec
