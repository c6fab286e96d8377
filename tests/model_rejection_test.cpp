// The cheap rejection ahead of the exact triangle test
// (model/watertight_rejection.h): it never drops a triangle that
// watertightIntersect keeps (a hit, or a miss with an ambiguity), on random
// rays and triangles at every magnitude, with and without a device's frame
// error, and on adversarial rays aimed exactly at vertices and edge points
// or a few float steps beside them; and it does drop clear misses.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "model/watertight.h"
#include "model/watertight_rejection.h"

namespace rayspec {
namespace {

struct Counts {
  int rejected = 0, kept = 0, tried = 0;
};

// Checks one (ray, triangle): a rejection implies the full test's drop.
void check(const DVec3& o, const DVec3& d, const DVec3& v0, const DVec3& v1, const DVec3& v2,
           const FrameError& err, Counts& c) {
  const WatertightRay w = prepareWatertightRay(o, d, err);
  const WatertightHit full = watertightIntersectPrepared(w, v0, v1, v2, err.vertex);
  // The split changes no value.
  const WatertightHit old = watertightIntersect(o, d, v0, v1, v2, err);
  ASSERT_EQ(full.hit, old.hit);
  ASSERT_EQ(full.ambiguity, old.ambiguity);
  ASSERT_EQ(full.t, old.t);
  ASSERT_EQ(full.t_err, old.t_err);
  ++c.tried;
  const bool kept = full.valid && (full.hit || full.ambiguity != TriAmbiguity::None);
  if (kept) ++c.kept;
  if (!watertightCertainMiss(w, v0, v1, v2, err.vertex)) return;
  ++c.rejected;
  ASSERT_FALSE(kept) << "rejected a kept triangle: o " << o[0] << " " << o[1] << " " << o[2]
                     << " d " << d[0] << " " << d[1] << " " << d[2] << " hit " << full.hit
                     << " amb " << static_cast<int>(full.ambiguity);
}

FrameError someError(std::mt19937_64& rng, double magnitude) {
  FrameError e;
  std::uniform_int_distribution<int> kind(0, 3);
  std::uniform_real_distribution<double> u(0, 1);
  const int k = kind(rng);
  if (k == 0) return e;  // robust tier, identity instance
  const double scale = k == 1 ? 1e-7 : k == 2 ? 1e-5 : 1e-3;
  for (int a = 0; a < 3; ++a) {
    e.origin[a] = u(rng) * scale * (1 + magnitude);
    e.direction[a] = u(rng) * scale;
    e.vertex[a] = k == 3 ? u(rng) * scale : 0;
  }
  return e;
}

TEST(Rejection, RandomRaysAndTriangles) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  Counts c;
  for (double m : {0.0, 1.0, 1e3, 1e5, 1e6, 1e9}) {
    for (int n = 0; n < 20000; ++n) {
      const double size = std::pow(10.0, 3 * u(rng));  // 1e-3 .. 1e3
      auto vert = [&] {
        return DVec3{float(m + size * u(rng)), float(m + size * u(rng)), float(size * u(rng))};
      };
      const DVec3 v0 = vert(), v1 = vert(), v2 = vert();
      const DVec3 o{float(m + 2 * size * u(rng)), float(m + 2 * size * u(rng)), float(3 * size)};
      const DVec3 d{float(u(rng)), float(u(rng)), float(-0.2 - std::fabs(u(rng)))};
      check(o, d, v0, v1, v2, someError(rng, m), c);
      if (HasFatalFailure()) return;
    }
  }
  // It must do something: most random pairs are clear misses.
  EXPECT_GT(c.rejected, c.tried / 3);
  EXPECT_GT(c.kept, c.tried / 50);
}

// Rays aimed exactly at vertices, at points of edges (k/8 along each) and at
// points a few float steps off them, at every magnitude, through a closed
// fan of triangles (every edge shared), straight and tilted, with and without
// frame error: the triangles a device may hit are all kept.
TEST(Rejection, EdgeAndVertexHittingRays) {
  std::mt19937_64 rng(11);
  Counts c;
  for (double m : {0.0, 1e2, 1e5, 1e6, 1e7}) {
    const DVec3 centre{m, m, 0};
    std::vector<DVec3> rim;
    for (int k = 0; k < 6; ++k) {
      const double a = k * 1.0471975511965976;
      rim.push_back({float(m + std::cos(a)), float(m + std::sin(a)), 0});
    }
    std::vector<DVec3> targets{centre};
    for (int k = 0; k < 6; ++k) {
      const DVec3& a = rim[k];
      const DVec3& b = rim[(k + 1) % 6];
      targets.push_back(a);
      for (int s = 1; s < 8; ++s) {
        const double f = s / 8.0;
        targets.push_back(
            {centre[0] + f * (a[0] - centre[0]), centre[1] + f * (a[1] - centre[1]), 0});
        targets.push_back({a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), 0});
      }
    }
    for (const DVec3& at : targets)
      for (int step : {0, 1, -1, 4, -4})
        for (const DVec3& d : {DVec3{0, 0, -1}, DVec3{0.25, -0.125, -1}, DVec3{-0.75, 0.5, -0.5}})
          for (int e = 0; e < 3; ++e) {
            const double x = std::nextafter(float(at[0]), float(at[0] + step)) +
                             step * 1e-7 * (1 + std::fabs(at[0]));
            const DVec3 o{x - 3 * d[0], at[1] - 3 * d[1], -3 * d[2]};
            FrameError err = e == 0 ? FrameError{} : someError(rng, m);
            for (int k = 0; k < 6; ++k) {
              check(o, d, centre, rim[k], rim[(k + 1) % 6], err, c);
              check(o, d, centre, rim[(k + 1) % 6], rim[k], err, c);  // the other winding
              if (HasFatalFailure()) return;
            }
          }
  }
  EXPECT_GT(c.rejected, 0);
  EXPECT_GT(c.kept, c.tried / 10);
}

TEST(Rejection, ClearMissesAreRejectedNaNNever) {
  const DVec3 v0{0, 0, 0}, v1{1, 0, 0}, v2{1, 1, 0}, d{0, 0, -1};
  const WatertightRay beside = prepareWatertightRay({2, 0.5, 5}, d, FrameError{});
  EXPECT_TRUE(watertightCertainMiss(beside, v0, v1, v2, {}));
  const WatertightRay inside = prepareWatertightRay({0.75, 0.25, 5}, d, FrameError{});
  EXPECT_FALSE(watertightCertainMiss(inside, v0, v1, v2, {}));
  // Just beside the hypotenuse: within the bound of a large origin error.
  FrameError large;
  large.origin = {0.02, 0.02, 0};
  const WatertightRay near = prepareWatertightRay({0.49, 0.51, 5}, d, large);
  EXPECT_FALSE(watertightCertainMiss(near, v0, v1, v2, {}));
  EXPECT_TRUE(watertightCertainMiss(prepareWatertightRay({0.49, 0.51, 5}, d, FrameError{}), v0, v1,
                                    v2, {}));
  EXPECT_FALSE(watertightCertainMiss(beside, {NAN, 0, 0}, v1, v2, {}));
  EXPECT_FALSE(watertightCertainMiss(beside, v0, {INFINITY, 0, 0}, v2, {}));
  EXPECT_FALSE(watertightCertainMiss(prepareWatertightRay({2, 0.5, 5}, {0, 0, 0}, FrameError{}), v0,
                                     v1, v2, {}));
}

}  // namespace
}  // namespace rayspec
