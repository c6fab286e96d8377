// The model's sphere decisions near rounding (R-PREC, "shader-arith").
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "model/model_engine.h"
#include "model/model_scene.h"
#include "model/sphere_error.h"
#include "model_support.h"
#include "parse/parse_case.h"

namespace rayspec {
namespace {

using namespace model_test;

// A sphere of radius 1 at the origin inscribed in a flat box (its x/y faces
// far from the rays below), the usual far-then-near reports.
Case sphereCase(std::vector<Ray> rays) {
  Geometry g;
  g.kind = Geometry::Kind::Aabbs;
  g.aabbs = {{-2, -2, -1, 2, 2, 1}};
  g.flags = kGeometryOpaque;
  Case c = baseCase({g}, std::move(rays));
  Stmt far;
  far.kind = Stmt::Kind::Report;
  far.t = op("sphere_far", {});
  far.hit_kind = lit(2);
  far.then_ = {count("far_accepted")};
  Stmt near = far;
  near.t = op("sphere_near", {});
  near.hit_kind = lit(1);
  near.then_ = {count("near_accepted")};
  c.pipeline.hit_groups[0].intersection = Program{ifThen(op("sphere_hit", {}), {far, near})};
  return c;
}

TEST(ModelSphere, TangentRayIsAmbiguousWithBothAnswers) {
  // 0: exactly tangent (disc == 0), 1: clearly through, 2: clearly missing
  // (inside the box), 3: a hair inside the tangent line.
  Case c =
      sphereCase({downRay(1.0f, 0), downRay(0.5f, 0), downRay(1.5f, 0), downRay(0.9999999f, 0)});
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  std::map<uint32_t, const RayAmbiguity*> amb;
  for (const RayAmbiguity& a : r.ambiguous) amb[a.ray] = &a;
  EXPECT_EQ(word(r, 1, "hit"), 1u);
  EXPECT_EQ(word(r, 2, "hit"), 0u);
  EXPECT_EQ(amb.count(1), 0u);
  EXPECT_EQ(amb.count(2), 0u);
  EXPECT_EQ(word(r, 0, "intersection_runs"), 1u);
  for (uint32_t ray : {0u, 3u}) {
    ASSERT_EQ(amb.count(ray), 1u) << ray;
    EXPECT_EQ(amb[ray]->reason, AmbiguityReason::ShaderArith) << ray;
    bool hit = false, miss = false;
    for (const Candidate& k : amb[ray]->candidates) {
      (k.hit ? hit : miss) = true;
      if (k.hit) {
        EXPECT_EQ(k.primitive, 0u);
      }
    }
    EXPECT_TRUE(hit && miss) << ray;
  }
  // The fast and robust tiers mark nothing.
  for (ModelTier tier : {ModelTier::Fast, ModelTier::Robust})
    EXPECT_TRUE(run(c, tier).ambiguous.empty());
  // The sandboxed what-if runs left the actual run's counters alone: the
  // model hits rays 0 (disc exactly 0), 1 and 3 once each.
  EXPECT_EQ(r.counters["far_accepted"], 3u);
  EXPECT_EQ(r.counters["near_accepted"], 3u);
  EXPECT_EQ(r.counters["closesthit"], 3u);
}

TEST(ModelSphere, NearlyTangentHitGetsAWiderTBoundThanACentralHit) {
  // 0: through the centre (disc large), 1: close to tangency but clearly
  // inside (disc small, so sqrt amplifies a device's rounding).
  Case c = sphereCase({downRay(0.0f, 0), downRay(0.999f, 0)});
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  EXPECT_EQ(word(r, 0, "hit"), 1u);
  EXPECT_EQ(word(r, 1, "hit"), 1u);
  std::map<uint32_t, float> bound;
  for (const TBound& b : r.t_bounds) bound[b.ray] = b.bound;
  ASSERT_EQ(bound.count(1), 1u) << "a near-tangent root needs more than the default tolerance";
  EXPECT_GT(bound[1], 1e-4f);
  if (bound.count(0)) {
    EXPECT_LT(bound[0], bound[1]);
  }
  EXPECT_TRUE(run(c, ModelTier::Fast).t_bounds.empty()) << "only the exact tier bounds t";
}

TEST(ModelSphere, RootNearTminIsAmbiguous) {
  // The ray starts just below the sphere (z = -1) going up: its near root is
  // ~tmin (0.001), its far root clear.
  Ray on_surface = downRay(0, 0, -1.001f);
  on_surface.direction = {0, 0, 1};
  Ray clear = downRay(0, 0, 0);  // from the centre: far root 1, clear
  Case c = sphereCase({on_surface, clear});
  Results r = run(c, ModelTier::Exact);
  ASSERT_EQ(r.statusText(), "ok");
  std::map<uint32_t, const RayAmbiguity*> amb;
  for (const RayAmbiguity& a : r.ambiguous) amb[a.ray] = &a;
  EXPECT_EQ(amb.count(1), 0u);
  EXPECT_EQ(word(r, 1, "hit"), 1u);
  EXPECT_NEAR(fword(r, 1, "hit_t"), 1.0f, 1e-6);
  ASSERT_EQ(amb.count(0), 1u);
  EXPECT_EQ(amb[0]->reason, AmbiguityReason::ShaderArith);
  EXPECT_EQ(word(r, 0, "hit"), 1u);
}

TEST(ModelSphere, ErrorBoundsAreTightForClearRays) {
  const std::array<float, 12> identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  const Vec3 bmin = {-1, -1, -1}, bmax = {1, 1, 1};
  const Vec3 o = {0.5f, 0, 5}, d = {0, 0, -1};
  const SphereError se = sphereError(bmin, bmax, o, d, objectRayError(identity, o, d));
  EXPECT_NEAR(se.disc, 0.75, 1e-9);
  EXPECT_GT(se.disc_err, 0.0);
  EXPECT_LT(se.disc_err, 1e-5 * 25);  // b * b = 25: conservative, not silly
  EXPECT_LT(se.near_err, 2e-4);
  EXPECT_LT(se.far_err, 2e-4);
  // A translation adds the rounding of its larger magnitudes.
  const std::array<float, 12> moved = {1, 0, 0, -1000, 0, 1, 0, 0, 0, 0, 1, 0};
  EXPECT_GT(objectRayError(moved, o, d).origin[0], objectRayError(identity, o, d).origin[0]);
}

// Whether `ray` (launch index `index`) grazes box k of instance mi within the
// model's error bound: the ray in the box's object space, the quadratic in
// float (operation by operation, as sphereRoots) and in double, printed.
bool grazesBox(const ModelInstance& mi, const Ray& ray, const std::array<float, 6>& bx,
               uint32_t index, size_t k) {
  const Vec3 bmin = {bx[0], bx[1], bx[2]}, bmax = {bx[3], bx[4], bx[5]};
  Vec3 of, df;
  double od[3], dd[3];
  for (int i = 0; i < 3; ++i) {
    of[i] = mi.inverse_f[i * 4] * ray.origin[0] + mi.inverse_f[i * 4 + 1] * ray.origin[1] +
            mi.inverse_f[i * 4 + 2] * ray.origin[2] + mi.inverse_f[i * 4 + 3];
    df[i] = mi.inverse_f[i * 4] * ray.direction[0] + mi.inverse_f[i * 4 + 1] * ray.direction[1] +
            mi.inverse_f[i * 4 + 2] * ray.direction[2];
    od[i] = mi.inverse[i * 4] * ray.origin[0] + mi.inverse[i * 4 + 1] * ray.origin[1] +
            mi.inverse[i * 4 + 2] * ray.origin[2] + mi.inverse[i * 4 + 3];
    dd[i] = mi.inverse[i * 4] * ray.direction[0] + mi.inverse[i * 4 + 1] * ray.direction[1] +
            mi.inverse[i * 4 + 2] * ray.direction[2];
  }
  // Float, operation by operation (sphereRoots), and double.
  Vec3 cf, hf;
  double cd[3], hd[3];
  for (int i = 0; i < 3; ++i) {
    cf[i] = (bmin[i] + bmax[i]) * 0.5f;
    hf[i] = (bmax[i] - bmin[i]) * 0.5f;
    cd[i] = (double(bmin[i]) + bmax[i]) * 0.5;
    hd[i] = (double(bmax[i]) - bmin[i]) * 0.5;
  }
  const float rf = std::min({hf[0], hf[1], hf[2]});
  const double rd = std::min({hd[0], hd[1], hd[2]});
  float af = 0, bf = 0, ccf = 0;
  double ad = 0, bd = 0, ccd = 0;
  const Vec3 ocf = {of[0] - cf[0], of[1] - cf[1], of[2] - cf[2]};
  af = df[0] * df[0] + df[1] * df[1] + df[2] * df[2];
  bf = ocf[0] * df[0] + ocf[1] * df[1] + ocf[2] * df[2];
  ccf = ocf[0] * ocf[0] + ocf[1] * ocf[1] + ocf[2] * ocf[2] - rf * rf;
  for (int i = 0; i < 3; ++i) {
    const double oc = od[i] - cd[i];
    ad += dd[i] * dd[i];
    bd += oc * dd[i];
    ccd += oc * oc;
  }
  ccd -= rd * rd;
  const float discf = bf * bf - af * ccf;
  const double discd = bd * bd - ad * ccd;
  const SphereRoots sr = sphereRoots(bmin, bmax, of, df);
  EXPECT_EQ(sr.disc, discf);
  const SphereError se =
      sphereError(bmin, bmax, of, df, objectRayError(mi.inverse_f, ray.origin, ray.direction));
  const double sd = std::sqrt(std::max(discd, 0.0));
  std::printf("ray %u box %zu: float a=%.9g b=%.9g cc=%.9g disc=%.9g near=%.9g far=%.9g\n", index,
              k, af, bf, ccf, discf, sr.t_near, sr.t_far);
  std::printf("ray %u box %zu: double a=%.17g b=%.17g cc=%.17g disc=%.17g near=%.17g far=%.17g\n",
              index, k, ad, bd, ccd, discd, (-bd - sd) / ad, (-bd + sd) / ad);
  std::printf("ray %u box %zu: bound disc_err=%.3g near_err=%.3g far_err=%.3g\n", index, k,
              se.disc_err, se.near_err, se.far_err);
  return std::fabs(double(discf)) <= se.disc_err;
}

// The finding on the NVIDIA H200: mixed-scene-1024 ray 638477 (x=525,
// y=623) grazes a ball; the model's numbers for that ray, and its verdict.
TEST(ModelSphere, MixedSceneRay638477IsTangent) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(RAYSPEC_SOURCE_DIR) / "cases";
  ParseResult p = parseCaseFile((root / "model/mixed-scene-1024.yaml").string(), root.string());
  ASSERT_TRUE(p.value);
  Case c = *p.value;
  const uint32_t index = 638477;
  ASSERT_GT(c.rays.rays.size(), index);
  const Ray ray = c.rays.rays[index];
  ModelScene scene;
  ASSERT_TRUE(buildModelScene(scene, c, ModelTier::Exact, true).ok());
  const ModelInstance& mi = scene.instances[1];
  const auto& aabbs = c.scene.blases[mi.blas].geometries[0].aabbs;
  bool tangent = false;
  for (size_t k = 0; k < aabbs.size(); ++k)
    tangent = grazesBox(mi, ray, aabbs[k], index, k) || tangent;
  EXPECT_TRUE(tangent);
  // The exact tier marks that ray alone ambiguous, with a hit and the other path legal.
  c.rays.rays = {ray};
  c.rays.width = c.rays.height = 1;
  const Plan plan = derivePlan(c);
  Results r = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
  ASSERT_EQ(r.statusText(), "ok");
  ASSERT_EQ(r.ambiguous.size(), 1u);
  EXPECT_EQ(r.ambiguous[0].reason, AmbiguityReason::ShaderArith);
  EXPECT_GE(r.ambiguous[0].candidates.size(), 2u);
  for (const Candidate& k : r.ambiguous[0].candidates)
    std::printf("legal: hit=%d instance=%u geometry=%u primitive=%u\n", k.hit, k.instance,
                k.geometry, k.primitive);
}

}  // namespace
}  // namespace rayspec
