// Case mutations of AABB primitives: a box a device never runs the
// intersection shader of (made inactive: NaN min X), chosen along the
// launch rays (object space, through the instance's inverse transform).
#include <cmath>
#include <limits>
#include <set>
#include <tuple>

#include "base/affine.h"
#include "base/slab.h"
#include "case/transform.h"
#include "fault/fault_impl.h"

namespace rayspec {
namespace {

using BoxKey = std::tuple<uint32_t, uint32_t, uint32_t>;  // blas, geometry, primitive

struct Crossing {
  BoxKey box;
  double entry;  // t0, before tmin when the ray starts inside
};

// Every active box the launch ray crosses within its interval.
std::vector<Crossing> crossings(const Case& c, const Ray& r) {
  std::vector<Crossing> out;
  for (const Instance& inst : c.scene.instances) {
    if (!inst.blas) continue;
    const DTransform inv = invertTransform(inst.transform);
    const DVec3 o = applyAffine(inv, toDouble(r.origin), 1),
                d = applyAffine(inv, toDouble(r.direction), 0);
    const Blas& b = c.scene.blases[*inst.blas];
    for (uint32_t g = 0; g < b.geometries.size(); ++g)
      for (uint32_t p = 0; p < b.geometries[g].aabbs.size(); ++p) {
        const auto& a = b.geometries[g].aabbs[p];
        if (std::isnan(a[0])) continue;
        const auto [t0, t1] = slabSpan({a[0], a[1], a[2]}, {a[3], a[4], a[5]}, o, d);
        if (t0 <= t1 && t1 >= r.tmin && std::max(t0, double(r.tmin)) <= r.tmax)
          out.push_back({{*inst.blas, g, p}, t0});
      }
  }
  return out;
}

std::string deactivate(Case& c, const std::set<BoxKey>& boxes, const std::string& why) {
  for (const auto& [b, g, p] : boxes)
    c.scene.blases[b].geometries[g].aabbs[p][0] = std::numeric_limits<float>::quiet_NaN();
  if (boxes.empty()) return {};
  return std::to_string(boxes.size()) + " boxes " + why + " made inactive";
}

}  // namespace

std::string boxEnteredFromInsideMissed(Case& c, ModelOptions&) {
  std::set<BoxKey> inside;
  for (const Ray& r : c.rays.rays)
    for (const Crossing& x : crossings(c, r))
      if (x.entry < r.tmin) inside.insert(x.box);
  return deactivate(c, inside, "that launch rays start inside");
}

// A device that takes an interval of zero length (tmin = tmax) as empty: the
// boxes such launch rays meet (inside, on a face or at a corner) are never
// offered to them. They are made inactive for every ray, so the fault is
// exactly this device's on a case whose rays meeting them are all of zero
// length (intersection/ and ray-query/zero-length-in-box).
std::string zeroLengthRayBoxMissed(Case& c, ModelOptions&) {
  std::set<BoxKey> met;
  for (const Ray& r : c.rays.rays)
    if (r.tmin == r.tmax)
      for (const Crossing& x : crossings(c, r)) met.insert(x.box);
  return deactivate(c, met, "that zero-length launch rays (tmin = tmax) meet");
}

std::string closestBoxSkipped(Case& c, ModelOptions&) {
  for (const Ray& r : c.rays.rays) {
    const std::vector<Crossing> xs = crossings(c, r);
    const Crossing* closest = nullptr;
    for (const Crossing& x : xs)
      if (!closest || std::max(x.entry, double(r.tmin)) < std::max(closest->entry, double(r.tmin)))
        closest = &x;
    if (closest && closest->entry > r.tmin)
      return deactivate(c, {closest->box}, "first crossed by a launch ray");
  }
  return {};
}

}  // namespace rayspec
