// Case mutations of AABB primitives: a box a device never runs the
// intersection shader of (made inactive: NaN min X), chosen along the
// launch rays (object space, through the instance's inverse transform).
#include <cmath>
#include <limits>
#include <set>
#include <tuple>

#include "case/transform.h"
#include "fault/fault_impl.h"

namespace rayspec {
namespace {

using D3 = std::array<double, 3>;
using BoxKey = std::tuple<uint32_t, uint32_t, uint32_t>;  // blas, geometry, primitive

D3 apply(const std::array<double, 12>& m, const Vec3& v, double w) {
  D3 r;
  for (int row = 0; row < 3; ++row)
    r[row] = m[row * 4] * v[0] + m[row * 4 + 1] * v[1] + m[row * 4 + 2] * v[2] + m[row * 4 + 3] * w;
  return r;
}

// Where the ray's line enters and leaves the box (t0 > t1: it does not).
std::pair<double, double> slab(const std::array<float, 6>& a, const D3& o, const D3& d) {
  double t0 = -std::numeric_limits<double>::infinity(), t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) {
      if (o[k] < a[k] || o[k] > a[k + 3]) return {1, 0};
      continue;
    }
    double n = (a[k] - o[k]) / d[k], f = (a[k + 3] - o[k]) / d[k];
    if (n > f) std::swap(n, f);
    t0 = std::max(t0, n);
    t1 = std::min(t1, f);
  }
  return {t0, t1};
}

struct Crossing {
  BoxKey box;
  double entry;  // t0, before tmin when the ray starts inside
};

// Every active box the launch ray crosses within its interval.
std::vector<Crossing> crossings(const Case& c, const Ray& r) {
  std::vector<Crossing> out;
  for (const Instance& inst : c.scene.instances) {
    if (!inst.blas) continue;
    const std::array<double, 12> inv = invertTransform(inst.transform);
    const D3 o = apply(inv, r.origin, 1), d = apply(inv, r.direction, 0);
    const Blas& b = c.scene.blases[*inst.blas];
    for (uint32_t g = 0; g < b.geometries.size(); ++g)
      for (uint32_t p = 0; p < b.geometries[g].aabbs.size(); ++p) {
        const auto& a = b.geometries[g].aabbs[p];
        if (std::isnan(a[0])) continue;
        const auto [t0, t1] = slab(a, o, d);
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

std::string closestBoxSkipped(Case& c, ModelOptions&) {
  for (const Ray& r : c.rays.rays) {
    const std::vector<Crossing> xs = crossings(c, r);
    const Crossing* closest = nullptr;
    for (const Crossing& x : xs)
      if (!closest || std::max(x.entry, double(r.tmin)) < std::max(closest->entry, double(r.tmin))) closest = &x;
    if (closest && closest->entry > r.tmin) return deactivate(c, {closest->box}, "first crossed by a launch ray");
  }
  return {};
}

}  // namespace rayspec
