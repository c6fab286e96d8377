// Why the exact tier's candidate boxes are padded by
//   pad = kBoxMagnitudeSteps u m + blasRayPads(BLAS) + 4 * vertex error,
//   blasRayPads = kZoneSteps u rho + (per instance) ray error,
// with u = 2^-24, m = the largest magnitude of the triangle's coordinates,
// rho = the largest distance (infinity norm, object space) from a ray origin
// to the BLAS's box, plus the box's extent. Before, the pad was 1e-5 m
// (~168 u m) plus 1e-5 of the instance translation: a whole grid cell at
// 1e5, ten cells at 1e6, each re-decided by every ray.
//
// Which triangles must be enumerated: those for which watertightIntersect
// returns a hit or an ambiguity (the others are dropped). It decides in the
// sheared frame (watertight.h): p_j = the vertices relative to the origin,
// projected along the direction. If the ray (as a line) misses the
// triangle's box grown by P in every axis, every point of the triangle lies
// at least P from the origin there in x or y: a point y of the triangle with
// sheared coordinates (a, b) lies (a, b, 0) from the line's point at y's
// depth. So P must cover how far from the triangle the test still answers
// a hit or an ambiguity, plus how far Embree's ray is from the model's:
//
// 1. The zone. An edge function e = L h (L the edge's sheared length, h the
//    origin's distance to the edge's line) is ambiguous while e <= bound.
//    With no device error, bound <= 4 A E + 2 r (A + E)^2 + O(E^2), A the
//    edge's largest |p| (<= 2 L for a ray within h <= L of it), and E
//    <= 8 u R per vertex (the rounding of x + s z with |s| <= 1 and of the
//    shear along the depth z; R = the largest |v - o|, which rho bounds). So
//    h <= 4 * 2 L * 8 u R / L + 2 r 4 L^2 / L = 64 u R + 32 u L <= 64 u rho
//    (rho >= R and rho >= L). The device's own errors (origin, direction,
//    vertices) add to the zone: through the instance's ray error below and
//    the vertex error in the pad. kZoneSteps = 128 leaves a factor 2 (on the
//    hard cases, tests/model_box_pad_test.cpp, 16 already suffices). Past
//    h > L the test still calls a triangle smaller than its rounding
//    degenerate from any distance: those far flags never meant a device may
//    hit it, and the former pads did not enumerate them either.
// 2. Embree's ray. Identity instance: Embree's object ray is the launch ray
//    itself (floats, the model's own); Embree's robust traversal then misjudges
//    a box by at most a few float steps of the distance it measures, which
//    kTraversalSteps of rho covers. Other instances: Embree inverts the float
//    transform and applies it in float, a few roundings of the inverse
//    translation and of the object-space origin; a device's own origin error
//    is of the same kind (frame_error.cpp: 2 u of the inverse translation
//    plus u of the origin for a scaled permutation, 8 u of every term for a
//    general transform). instancePad (frame_error.h: 8 u, resp. 32 u, of the
//    translation's terms) plus kTraversalSteps of the object-space origin's
//    magnitude (the former reach term) covers both.
// 3. Float. The box is handed to Embree in float, rounded outward
//    (ownTriangleBounds), and kBoxMagnitudeSteps u m more absorbs the
//    rounding of the vertices the box is built from.
//
// The ray origins: the launch rays' and, for rays traced from a shader
// (usually from a hit point), the corners of the scene's world box. rho is
// capped at 1e5 times the BLAS's extent (as the reach was): rays from far
// away that meet another instance must not blow the boxes up.
#include "model/box_pad.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "base/affine.h"
#include "base/float_steps.h"
#include "case/transform.h"
#include "model/frame_error.h"
#include "model/watertight.h"

namespace rayspec {

namespace {

constexpr double kZoneSteps = 128.0;
// Float steps (relative) of a ray origin's distance that Embree's box test
// may be off by: about 8 * 2^-23.
constexpr double kTraversalSteps = 1e-6;
constexpr double kReachCap = 1e5;

struct Box {
  DVec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  void add(const DVec3& p) {
    for (int k = 0; k < 3; ++k)
      if (std::isfinite(p[k])) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  bool empty() const { return !(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2]); }
  double extent() const { return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}); }
  // Infinity-norm distance of p to the box (0 inside).
  double distance(const DVec3& p) const {
    double d = 0;
    for (int k = 0; k < 3; ++k) d = std::max({d, lo[k] - p[k], p[k] - hi[k]});
    return d;
  }
};

Box blasBox(const Blas& b) {
  Box box;
  for (const Geometry& g : b.geometries) {
    const DTransform m = toDouble(g.transform.value_or(kIdentity));
    for (const Vec3& v : g.vertices) box.add(applyAffine(m, toDouble(v), 1.0));
    for (const auto& a : g.aabbs) {
      box.add({a[0], a[1], a[2]});
      box.add({a[3], a[4], a[5]});
    }
  }
  return box;
}

DVec3 corner(const Box& b, int i) {
  return {(i & 1) ? b.hi[0] : b.lo[0], (i & 2) ? b.hi[1] : b.lo[1], (i & 4) ? b.hi[2] : b.lo[2]};
}

// The BLASes' boxes and the ray origins (box_pad.h): the launch rays', and
// the corners of the world box.
struct PadScene {
  std::vector<Box> boxes;
  std::vector<DVec3> origins;
};

PadScene padScene(const Case& c, double exact_pairs) {
  PadScene ps;
  const size_t nb = c.scene.blases.size();
  ps.boxes.resize(nb);
  for (size_t b = 0; b < nb; ++b) ps.boxes[b] = blasBox(c.scene.blases[b]);
  std::vector<DVec3>& origins = ps.origins;
  origins.reserve(c.rays.rays.size() + 8);
  for (const Ray& r : c.rays.rays) origins.push_back({r.origin[0], r.origin[1], r.origin[2]});
  Box world;
  for (const Instance& inst : c.scene.instances) {
    if (!inst.blas || *inst.blas >= nb || ps.boxes[*inst.blas].empty()) continue;
    const DTransform m = toDouble(inst.transform);
    for (int i = 0; i < 8; ++i) world.add(applyAffine(m, corner(ps.boxes[*inst.blas], i), 1.0));
  }
  if (!world.empty())
    for (int i = 0; i < 8; ++i) origins.push_back(corner(world, i));
  // Many instances times many origins (accel/size-instances: 2^16 x 2^16):
  // the origins' bounding box corners instead. The distance to a box and |x|
  // are convex in the origin, so their largest value over the corners is at
  // least that over the origins: a pad as large or larger, never smaller.
  if (double(origins.size()) * double(c.scene.instances.size()) > exact_pairs) {
    Box hull;
    for (const DVec3& q : origins) hull.add(q);
    origins.clear();
    for (int i = 0; i < 8; ++i) origins.push_back(corner(hull, i));
  }
  return ps;
}

}  // namespace

std::vector<double> blasRayPads(const Case& c, double exact_pairs) {
  const PadScene ps = padScene(c, exact_pairs);
  const size_t nb = c.scene.blases.size();
  const std::vector<Box>& boxes = ps.boxes;
  const std::vector<DVec3>& origins = ps.origins;
  std::vector<double> pad(nb, 0.0);
  for (const Instance& inst : c.scene.instances) {
    if (!inst.blas || *inst.blas >= nb || boxes[*inst.blas].empty()) continue;
    const Box& box = boxes[*inst.blas];
    const DTransform inv = invertTransform(inst.transform);
    const bool identity = instanceForm(inst.transform) == InstanceForm::Identity;
    const double cap = kReachCap * box.extent();
    double rho = 0, reach = 0;
    for (const DVec3& q : origins) {
      const DVec3 o = identity ? q : applyAffine(inv, q, 1.0);
      const double d = box.distance(o);
      if (std::isfinite(d)) rho = std::max(rho, d);
      for (double x : o)
        if (std::isfinite(x)) reach = std::max(reach, std::fabs(x));
    }
    rho = std::min(rho + box.extent(), cap);
    double p = kZoneSteps * kUnitRoundoff * rho + kTraversalSteps * rho;
    if (!identity) p += instancePad(inv, inst.transform) + kTraversalSteps * std::min(reach, cap);
    if (std::isfinite(p)) pad[*inst.blas] = std::max(pad[*inst.blas], p);
  }
  return pad;
}

namespace {

// One instance's part of blasBoxPads: the largest bound (model/box_bound.h)
// over the origins, for a box within the BLAS's box.
double instanceBoxPad(const Instance& inst, const Box& box, const std::vector<DVec3>& origins) {
  const DTransform inv = invertTransform(inst.transform);
  std::array<float, 12> inv_f;
  for (int k = 0; k < 12; ++k) inv_f[k] = static_cast<float>(inv[k]);
  const InstanceForm form = instanceForm(inst.transform);
  const DTransform m = toDouble(inst.transform);
  double magnitude = 0, world = 0;  // the box's largest |x|, in object and in world space
  for (int i = 0; i < 8; ++i) {
    magnitude = std::max(magnitude, largestMagnitude(corner(box, i)));
    world = std::max(world, largestMagnitude(applyAffine(m, corner(box, i), 1.0)));
  }
  double pad = 0;
  for (const DVec3& q : origins) {
    FrameError err;
    objectRayFrameError(form, inv, inv_f, q, {1, 1, 1}, err);
    const DVec3 o = form == InstanceForm::Identity ? q : applyAffine(inv, q, 1.0);
    const double p = kDeviceRelTolerance * std::max(largestMagnitude(o), magnitude) +
                     largestMagnitude(err.origin) +
                     (largestMagnitude(q) + world) * largestMagnitude(err.direction);
    if (std::isfinite(p)) pad = std::max(pad, p);
  }
  return pad;
}

}  // namespace

std::vector<double> blasBoxPads(const Case& c, double exact_pairs) {
  const size_t nb = c.scene.blases.size();
  std::vector<double> pad(nb, 0.0);
  bool boxes = false;
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries) boxes = boxes || g.kind == Geometry::Kind::Aabbs;
  if (!boxes) return pad;
  const PadScene ps = padScene(c, exact_pairs);
  for (const Instance& inst : c.scene.instances) {
    if (!inst.blas || *inst.blas >= nb || ps.boxes[*inst.blas].empty()) continue;
    const double p = kBoxPadMargin * instanceBoxPad(inst, ps.boxes[*inst.blas], ps.origins);
    pad[*inst.blas] = std::max(pad[*inst.blas], p);
  }
  return pad;
}

}  // namespace rayspec
