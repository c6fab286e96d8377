#include "case/huge_rays.h"

#include <algorithm>
#include <cmath>

#include "base/affine.h"
#include "base/slab.h"
#include "case/inactive.h"
#include "case/transform.h"
#include "program/ops.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

// The distance from `o` to the box [lo, hi].
double boxDistance(const DVec3& lo, const DVec3& hi, const DVec3& o) {
  double sum = 0;
  for (int k = 0; k < 3; ++k) {
    const double out = std::max({lo[k] - o[k], 0.0, o[k] - hi[k]});
    sum += out * out;
  }
  return std::sqrt(sum);
}

// Whether a program of a stage other than intersection tests a sphere:
// only a ray query's aabb block may (program/op_table.h).
bool queryTestsSphere(const Pipeline& p) {
  bool tests = false;
  const auto visit = [&](const Program& program) {
    tests = tests || testsInscribedSphere(program);
  };
  visit(p.raygen);
  for (const Program& program : p.other_raygens) visit(program);
  for (const Program& program : p.miss) visit(program);
  for (const Program& program : p.callables) visit(program);
  for (const HitGroup& h : p.hit_groups)
    for (const auto* program : {&h.closest_hit, &h.any_hit})
      if (*program) visit(**program);
  return tests;
}

// Where the boxes of geometry `g` of `inst`'s BLAS meet a sphere test for
// `r`: the hit group it reaches, if its intersection program tests one
// (nullopt inside: a ray query's block does); nullopt: none.
std::optional<std::optional<size_t>> sphereTester(const Case& c, const Instance& inst, const Ray& r,
                                                  uint32_t g, bool queries) {
  const size_t group = size_t{inst.sbt_offset} + r.sbt_offset + size_t{g} * r.sbt_stride;
  const auto& groups = c.pipeline.hit_groups;
  if (group < groups.size() && groups[group].intersection &&
      testsInscribedSphere(*groups[group].intersection))
    return std::optional<size_t>(group);
  if (queries) return std::optional<size_t>();
  return std::nullopt;
}

// The first box of `inst` that ray `r` (object space o + t d) meets from
// far away, with a sphere-testing hit group.
std::optional<HugeSphereRay> hugeAtInstance(const Case& c, const Instance& inst, const Ray& r,
                                            const DVec3& o, const DVec3& d, bool queries) {
  const Blas& blas = c.scene.blases[*inst.blas];
  for (uint32_t g = 0; g < blas.geometries.size(); ++g) {
    const Geometry& geometry = blas.geometries[g];
    if (geometry.kind != Geometry::Kind::Aabbs) continue;
    const std::optional<std::optional<size_t>> tester = sphereTester(c, inst, r, g, queries);
    if (!tester) continue;
    for (uint32_t p = 0; p < geometry.primitiveCount(); ++p) {
      if (primitiveInactive(geometry, p)) continue;
      const auto& b = geometry.aabbs[p];
      DVec3 lo{}, hi{};
      for (int k = 0; k < 3; ++k) {
        const double grow = double(b[3 + k]) - double(b[k]);  // conservative: its own extent
        lo[k] = b[k] - grow;
        hi[k] = b[3 + k] + grow;
      }
      const double distance =
          boxDistance(toDouble(Vec3{b[0], b[1], b[2]}), toDouble(Vec3{b[3], b[4], b[5]}), o);
      if (distance < kHugeRayDistance || slabSpan(lo, hi, o, d, {r.tmin, r.tmax}).empty()) continue;
      return HugeSphereRay{0, 0, g, p, *tester, distance};
    }
  }
  return std::nullopt;
}

}  // namespace

bool testsInscribedSphere(const Program& p) {
  bool tests = false;
  walkExpressions(
      p, [&](const Expr& e) { tests = tests || (e.kind == Expr::Kind::Op && isSphereOp(e.op)); });
  return tests;
}

std::optional<HugeSphereRay> hugeRayAtSphereBox(const Case& c) {
  const bool queries = queryTestsSphere(c.pipeline);
  for (size_t i = 0; i < c.rays.rays.size(); ++i) {
    const Ray& r = c.rays.rays[i];
    if (r.flags & kRaySkipAabbs) continue;
    for (uint32_t n = 0; n < c.scene.instances.size(); ++n) {
      const Instance& inst = c.scene.instances[n];
      if (!inst.blas || !(r.cull_mask & inst.mask & 0xFF)) continue;
      const DTransform to_object = invertTransform(inst.transform);
      const DVec3 o = applyAffine(to_object, toDouble(r.origin), 1);
      const DVec3 d = applyAffine(to_object, toDouble(r.direction), 0);
      if (std::optional<HugeSphereRay> huge = hugeAtInstance(c, inst, r, o, d, queries)) {
        huge->ray = i;
        huge->instance = n;
        return huge;
      }
    }
  }
  return std::nullopt;
}

}  // namespace rayspec
