// Exact tier: whether a box is surely a candidate depends on the ray's
// interval, not on its line alone (R-AABB-CONS, R-PREC). A ray whose interval
// lies well inside the box (a zero-length ray, tmin = tmax, at an inner point)
// is clear; one whose interval only reaches the box's surface (a zero-length
// ray at a corner or on a face, or an interval ending exactly where the line
// enters the box) is ambiguous, hit and miss both legal, though its line
// crosses the box. Before the fix those rays were clear hits, and lavapipe
// 25.0.7 misses a zero-length ray at a corner (intersection/zero-length-in-box).
#include <gtest/gtest.h>

#include "model_support.h"

namespace rayspec {
namespace {

using namespace model_test;

Ray ray(Vec3 origin, Vec3 direction, float tmin, float tmax) {
  Ray r;
  r.origin = origin;
  r.direction = direction;
  r.tmin = tmin;
  r.tmax = tmax;
  return r;
}

// Box [-1, 1]^3 whose intersection program reports tmin (the ray's one point
// for a zero-length ray).
Case boxCase(std::vector<Ray> rays) {
  Case c = baseCase({boxes({{-1, -1, -1, 1, 1, 1}})}, std::move(rays));
  Stmt rep;
  rep.kind = Stmt::Kind::Report;
  rep.t = bi("ray_tmin");
  rep.hit_kind = lit(1);
  c.pipeline.hit_groups[0].intersection = Program{rep};
  return c;
}

TEST(ModelZeroLengthBox, InnerPointIsClearSurfacePointsAmbiguous) {
  Case c = boxCase({
      ray({0.25f, 0.5f, -0.375f}, {0, 0, 1}, 0, 0),  // 0: inner point: hit at t = 0
      ray({1, 1, 1}, {-1, -1, -1}, 0, 0),            // 1: corner, line crossing the box
      ray({1, 0.25f, 0.5f}, {1, 0, 0}, 0, 0),        // 2: face, line crossing the box
      ray({0.25f, 0.5f, 5}, {0, 0, -1}, 0, 4),       // 3: interval ends on the top face
      ray({0.25f, 0.5f, 5}, {0, 0, -1}, 6, 9),       // 4: interval starts on the bottom face
      ray({0.25f, 0.5f, 5}, {0, 0, -1}, 0, 4.5f),    // 5: interval enters the box: hit
  });
  const Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  const auto amb = byRay(r);
  for (uint32_t clear : {0u, 5u}) {
    EXPECT_EQ(amb.count(clear), 0u) << clear;
    EXPECT_EQ(word(r, clear, "hit"), 1u) << clear;
  }
  EXPECT_EQ(fword(r, 0, "hit_t"), 0.0f);
  for (uint32_t surface : {1u, 2u, 3u, 4u}) {
    ASSERT_EQ(amb.count(surface), 1u) << surface;
    EXPECT_EQ(amb.at(surface)->reason, AmbiguityReason::AabbFace) << surface;
    const auto answers = legal(*amb.at(surface));
    EXPECT_EQ(answers.size(), 2u) << surface << ": the box and a miss";
    EXPECT_EQ(answers.count({~0u, ~0u, ~0u}), 1u) << surface;
  }
}

}  // namespace
}  // namespace rayspec
