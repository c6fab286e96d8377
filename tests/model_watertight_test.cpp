// The exact tier's triangle test and its error bound (model/watertight.h)
// and the frame errors that feed it (model/frame_error.h).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "case/transform.h"
#include "model/frame_error.h"
#include "model/in_plane.h"
#include "model/sphere_error.h"
#include "model/watertight.h"
#include "model/watertight_rejection.h"

namespace rayspec {
namespace {

constexpr double kU = 5.9604644775390625e-08;  // 2^-24

TEST(Watertight, InsideOutsideEdge) {
  DVec3 v0{-1, -1, 0}, v1{1, -1, 0}, v2{1, 1, 0};
  auto h = watertightIntersect({0.5, -0.5, 5}, {0, 0, -1}, v0, v1, v2);
  EXPECT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 5.0, 1e-12);
  EXPECT_EQ(h.ambiguity, TriAmbiguity::None);
  EXPECT_FALSE(watertightIntersect({-0.5, 0.5, 5}, {0, 0, -1}, v0, v1, v2).hit);
  auto e = watertightIntersect({0.25, 0.25, 5}, {0, 0, -1}, v0, v1, v2);  // on the diagonal
  EXPECT_EQ(e.ambiguity, TriAmbiguity::Edge);
  auto v = watertightIntersect({1, 1, 5}, {0, 0, -1}, v0, v1, v2);
  EXPECT_EQ(v.ambiguity, TriAmbiguity::Vertex);
  // degenerate (line) triangle never hits
  EXPECT_FALSE(watertightIntersect({0, 0, 5}, {0, 0, -1}, {-1, 0, 0}, {0, 0, 0}, {1, 0, 0}).hit);
}

// A ray exactly through an edge shared by two triangles, or through a vertex
// closed all around by a fan, hits exactly one of them (the perturbation of
// watertight.cpp), in either winding, along any direction.
TEST(Watertight, ExactlyOneTriangleOfASharedEdgeOrVertex) {
  const DVec3 c{0, 0, 0};
  std::vector<DVec3> rim;
  for (int k = 0; k < 8; ++k) {
    const double a = k * 0.78539816339744830962;
    rim.push_back({std::cos(a), std::sin(a), 0});
  }
  rim[2] = {0, 1, 0};  // exact axis points: rays along the spokes hit edges exactly
  rim[4] = {-1, 0, 0};
  rim[0] = {1, 0, 0};
  rim[6] = {0, -1, 0};
  for (const DVec3& d : {DVec3{0, 0, -1}, DVec3{0, 0, 1}, DVec3{0.5, 0.25, -1}})
    for (bool flip : {false, true})
      for (const DVec3& at :
           {DVec3{0, 0, 0}, DVec3{0.5, 0, 0}, DVec3{0, -0.25, 0}, DVec3{-0.125, 0, 0}}) {
        int hits = 0;
        for (int k = 0; k < 8; ++k) {
          const DVec3& a = rim[k];
          const DVec3& b = rim[(k + 1) % 8];
          const DVec3 o{at[0] - 4 * d[0], at[1] - 4 * d[1], -4 * d[2]};
          hits +=
              (flip ? watertightIntersect(o, d, c, b, a) : watertightIntersect(o, d, c, a, b)).hit;
        }
        EXPECT_EQ(hits, 1) << at[0] << " " << at[1] << " d " << d[0] << " flip " << flip;
      }
}

// The same unit triangle and rays, translated by m in x and y: the bound
// lives in the translated frame, so the answers never change with m.
TEST(Watertight, TranslationChangesNothing) {
  for (double m : {0.0, 1e3, 1e5, 1e6, 1e7, 1e9}) {
    const DVec3 v0{m, m, 0}, v1{m + 1, m, 0}, v2{m + 1, m + 1, 0};
    const DVec3 down{0, 0, -1}, tilted{0.25, -0.125, -1};
    for (const DVec3& d : {down, tilted}) {
      auto ray = [&](double x, double y) {
        return watertightIntersect({m + x - 5 * d[0], m + y - 5 * d[1], 5}, d, v0, v1, v2);
      };
      const WatertightHit centre = ray(2.0 / 3, 1.0 / 3), edge = ray(0.5, 0.5), vertex = ray(1, 0);
      EXPECT_TRUE(centre.hit) << m;
      EXPECT_EQ(centre.ambiguity, TriAmbiguity::None) << m;
      EXPECT_NEAR(centre.t, 5.0, 1e-9 * (1 + m));
      EXPECT_EQ(edge.ambiguity, TriAmbiguity::Edge) << m;
      EXPECT_EQ(vertex.ambiguity, TriAmbiguity::Vertex) << m;
      EXPECT_EQ(ray(2.0 / 3, -0.5).ambiguity, TriAmbiguity::None) << m << ": clearly outside";
    }
  }
}

// A ray 0.01 outside the hypotenuse of the unit triangle (edge function
// -0.01 * sqrt(2) * sqrt(2) = -0.02 in the sheared frame): clear when a
// device's origin is exact, ambiguous once its origin may be off by more
// than the distance, whatever the absolute coordinates.
TEST(Watertight, OriginErrorMovesTheTriangleRigidly) {
  const DVec3 v0{0, 0, 0}, v1{1, 0, 0}, v2{1, 1, 0}, d{0, 0, -1}, o{0.49, 0.51, 5};
  EXPECT_EQ(watertightIntersect(o, d, v0, v1, v2).ambiguity, TriAmbiguity::None);
  FrameError small, large;
  small.origin = {0.004, 0.004, 0.004};  // shifts the edge function by at most 0.008
  large.origin = {0.02, 0.02, 0.0};      // by up to 0.04
  EXPECT_EQ(watertightIntersect(o, d, v0, v1, v2, small).ambiguity, TriAmbiguity::None);
  const WatertightHit h = watertightIntersect(o, d, v0, v1, v2, large);
  EXPECT_FALSE(h.hit);
  EXPECT_EQ(h.ambiguity, TriAmbiguity::Edge);
  // A vertex error acts the same way (per vertex, with the edges' extent).
  FrameError vertex;
  vertex.vertex = {0.02, 0.02, 0};
  EXPECT_NE(watertightIntersect(o, d, v0, v1, v2, vertex).ambiguity, TriAmbiguity::None);
}

// An edge-on triangle is degenerate; a vertex with its two edges near
// and the third clear is a vertex even when the bound is large.
TEST(Watertight, NearEdgeCountLabels) {
  const DVec3 d{0, 0, -1};
  EXPECT_EQ(watertightIntersect({0.2, 0, 5}, d, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}).ambiguity,
            TriAmbiguity::Degenerate);
  FrameError big;
  big.origin = {0.3, 0.3, 0};  // the whole triangle's area is within the error
  EXPECT_EQ(watertightIntersect({0, 0, 5}, d, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, big).ambiguity,
            TriAmbiguity::Vertex);
}

// A ray nearly in a tilted triangle's plane (y = z), its line crossing the
// plane beside the triangle (t 8, x 3) after running a few float steps
// under it: where the determinant is within its bound, no edge function's
// sign is sure (nearlyInPlane, watertight.cpp: lavapipe 25.0.7 hits such
// rays), so the test answers in_plane (a device's hit anywhere across, or a
// miss), not a clear miss; farther from the plane it stays clear, and the
// cheap rejection drops only what the full test drops.
TEST(Watertight, ARayNearlyInTheTrianglesPlaneIsNotClearlyOutside) {
  const DVec3 v0{-1, -1, -1}, v1{1, -1, -1}, v2{0, 1, 1};
  int near = 0;
  for (double step = 1e-11; step < 1e-3; step *= 1.5) {
    const DVec3 o{-5, -8 * step, 0}, d{1, step, 0};
    const WatertightRay w = prepareWatertightRay(o, d, {});
    const WatertightHit h = watertightIntersectPrepared(w, v0, v1, v2, {});
    EXPECT_FALSE(h.hit) << step;
    if (h.in_plane) {
      ++near;
      EXPECT_EQ(h.ambiguity, TriAmbiguity::Degenerate) << step;
      EXPECT_FALSE(watertightCertainMiss(w, v0, v1, v2, {})) << step;
    }
    if (step > 1e-5) {
      EXPECT_EQ(h.ambiguity, TriAmbiguity::None) << step;
    }
  }
  EXPECT_GT(near, 0);
}

// fuzz/seed-120327 (NVIDIA 580 hit it at t 2.2276): the world ray lies
// exactly in the plane of a triangle of an instance scaled by (1.625, 1,
// 1.125); the model's double inverse (1 / 1.625 is not a double) leaves the
// object-space ray a rounding off the plane: a determinant not exactly 0 but
// within its bound, every edge function within its bound (no side sure at
// all). That is the ray in the plane as much as a zero determinant is
// (in_plane), not a degenerate triangle whose t (a ratio of roundings) puts
// it outside the interval. A triangle the ray crosses stays no in-plane one.
TEST(Watertight, ARayInThePlaneOfAScaledInstancesTriangleIsInPlane) {
  const Transform m = {1.625f, 0, 0, 0.75f, 0, 1, 0, -0.125f, 0, 0, 1.125f, 1.125f};
  const DTransform inv = invertTransform(m);
  std::array<float, 12> inv_f{};
  for (int k = 0; k < 12; ++k) inv_f[k] = static_cast<float>(inv[k]);
  const DVec3 world_o{5.37109375, 0.75, 3.76171875}, world_d{-2.28515625, -0.875, -1.01953125};
  FrameError err;
  objectRayFrameError(instanceForm(m), inv, inv_f, world_o, world_d, err);
  const DVec3 o = applyAffine(inv, world_o, 1.0), d = applyAffine(inv, world_d, 0.0);
  const DVec3 v0{-1.375, -1.75, -0.375}, v1{0.5, -1.625, 0.625}, v2{-0.125, -0.625, 0.5};
  const WatertightHit h = watertightIntersect(o, d, v0, v1, v2, err);
  EXPECT_TRUE(h.in_plane);
  EXPECT_FALSE(h.hit) << "the model's own answer in the plane";
  const std::optional<Span> across = inPlaneSpan(prepareWatertightRay(o, d, err), v0, v1, v2, {});
  ASSERT_TRUE(across.has_value());
  EXPECT_LE(across->t0, 2.2275862);
  EXPECT_GE(across->t1, 2.2275862) << "the device's hit lies in the span";
  const WatertightHit through = watertightIntersect(o, {0, 0, -1}, v0, v1, v2, err);
  EXPECT_FALSE(through.in_plane);
}

// fuzz/seed-120531 ray 5: from 3.5e6 away through a translated triangle's
// edge; the device's origin error (a float step of the translated origin)
// puts every edge function and the determinant within their bounds, but the
// line crosses the plane: a degenerate candidate, not one in the plane.
TEST(Watertight, AFarRayThroughATriangleIsNotInItsPlane) {
  const Transform m = {1, 0, 0, 1.5f, 0, 1, 0, -1.5f, 0, 0, 1, 0.125f};
  const DTransform inv = invertTransform(m);
  std::array<float, 12> inv_f{};
  for (int k = 0; k < 12; ++k) inv_f[k] = static_cast<float>(inv[k]);
  const DVec3 world_o{-3587498.5, -1537500.25, 1537500.5}, world_d{3587500, 1537500, -1537500};
  FrameError err;
  objectRayFrameError(instanceForm(m), inv, inv_f, world_o, world_d, err);
  const DVec3 o = applyAffine(inv, world_o, 1.0), d = applyAffine(inv, world_d, 0.0);
  const WatertightHit h = watertightIntersect(o, d, {0.125, 0.5, -0.5}, {1.875, -0.375, -0.25},
                                              {-1.375, 1.125, -0.375}, err);
  EXPECT_FALSE(h.in_plane);
  EXPECT_EQ(h.ambiguity, TriAmbiguity::Degenerate);
}

// Lavapipe fuzz seed 140242, reduced: a ray along a rotated instance's
// triangle in z = 0, its object-space line 1e-8 under the plane and
// crossing it behind the origin (t -0.47), with the rotation's frame error:
// every edge function and the determinant lie within their bounds (a sliver
// of a projection around the ray), so no sign is sure: in_plane (lavapipe
// hits it), not the clear miss it was.
TEST(Watertight, ARayInTheRoundedPlaneWithEveryEdgeNearIsInPlane) {
  const DVec3 v0{-1.625, -0.0625, 0}, v1{1.125, -0.0625, 0}, v2{1.125, 1.5625, 0};
  const DVec3 o{0.2656249947262339, 0.1406251114013619, -8.898396033907296e-09};
  const DVec3 d{-0.1718749982658384, 0.47395829813156276, -1.897618474855367e-08};
  FrameError err;
  err.origin = {1e-7, 1e-7, 1e-7};
  err.direction = {1e-7, 1e-7, 1e-7};
  const WatertightHit h =
      watertightIntersectPrepared(prepareWatertightRay(o, d, err), v0, v1, v2, {});
  EXPECT_FALSE(h.hit);
  EXPECT_TRUE(h.in_plane);
  // Without the frame error the line is clearly off: no in-plane answer.
  EXPECT_FALSE(
      watertightIntersectPrepared(prepareWatertightRay(o, d, {}), v0, v1, v2, {}).in_plane);
}

TEST(FrameError, InstanceForms) {
  EXPECT_EQ(instanceForm(kIdentity), InstanceForm::Identity);
  EXPECT_EQ(instanceForm({1, 0, 0, 1e5f, 0, 1, 0, 1e5f, 0, 0, 1, 0}),
            InstanceForm::ScaledPermutation);
  EXPECT_EQ(instanceForm({0, 3, 0, 0, -2, 0, 0, 0, 0, 0, 0.5f, 7}),
            InstanceForm::ScaledPermutation);
  EXPECT_EQ(instanceForm({0.6f, -0.8f, 0, 0, 0.8f, 0.6f, 0, 0, 0, 0, 1, 0}), InstanceForm::General);
}

// Identity: no error. A translation: a couple of float steps of the
// translation (not of the world origin's magnitude times the transform's).
// General: sphere_error.h's objectRayError.
TEST(FrameError, ObjectRayErrorPerForm) {
  FrameError e;
  const std::array<double, 12> id = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  std::array<float, 12> idf{};
  for (int k = 0; k < 12; ++k) idf[k] = static_cast<float>(id[k]);
  objectRayFrameError(InstanceForm::Identity, id, idf, {1e6, 1e6, 5}, {0, 0, -1}, e);
  EXPECT_EQ(e.origin, (DVec3{0, 0, 0}));
  EXPECT_EQ(e.direction, (DVec3{0, 0, 0}));

  std::array<double, 12> tr = id;
  tr[3] = tr[7] = -1e6;
  std::array<float, 12> trf = idf;
  trf[3] = trf[7] = -1e6f;
  objectRayFrameError(InstanceForm::ScaledPermutation, tr, trf, {1e6 + 0.25, 1e6 + 0.5, 5},
                      {0, 0, -1}, e);
  EXPECT_NEAR(e.origin[0], 2 * kU * 1e6 + kU * 0.25, 1e-12);
  EXPECT_NEAR(e.origin[1], 2 * kU * 1e6 + kU * 0.5, 1e-12);
  EXPECT_NEAR(e.origin[2], kU * 5, 1e-12);
  EXPECT_EQ(e.direction, (DVec3{0, 0, 0}));
  EXPECT_LT(e.origin[0], 0.0625 * 2.0) << "within two float steps at 1e6";

  const std::array<double, 12> rot = {0.6, 0.8, 0, 0, -0.8, 0.6, 0, 0, 0, 0, 1, 0};
  std::array<float, 12> rotf{};
  for (int k = 0; k < 12; ++k) rotf[k] = static_cast<float>(rot[k]);
  objectRayFrameError(InstanceForm::General, rot, rotf, {3, 4, 5}, {0, 0, -1}, e);
  const ObjectRayError want = objectRayError(rotf, {3, 4, 5}, {0, 0, -1});
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(e.origin[k], want.origin[k]);
    EXPECT_EQ(e.direction[k], want.direction[k]);
  }
}

TEST(FrameError, GeometryTransformVertexError) {
  EXPECT_EQ(geometryVertexError(kIdentity, {{1e6f, 0, 0}}), (DVec3{0, 0, 0}));
  const DVec3 e =
      geometryVertexError({2, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0}, {{1, 2, 3}, {-4, 0, 0}});
  EXPECT_NEAR(e[0], 4 * kU * (8 + 10), 1e-15);  // the larger of |2*1|+10 and |2*-4|+10
  EXPECT_NEAR(e[1], 4 * kU * 2, 1e-15);
  EXPECT_NEAR(e[2], 4 * kU * 3, 1e-15);
}

}  // namespace
}  // namespace rayspec
