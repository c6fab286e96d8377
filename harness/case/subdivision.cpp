// Seeded random non-planar subdivision generator.
#include "case/subdivision.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "case/seeded_random.h"

namespace rayspec {
namespace {

using Tri = std::array<uint32_t, 3>;

// Twice the signed area of (a, b, c) projected on z = 0.
double doubledArea(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (double(b[0]) - a[0]) * (double(c[1]) - a[1]) -
         (double(b[1]) - a[1]) * (double(c[0]) - a[0]);
}

Vec3 toFloat(double x, double y, double z) {
  return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
}

// Whether triangle (a, b, c) is no thinner (in x and y) than `least`: its
// doubled area at least `least` times its longest side.
bool thickEnough(const Vec3& a, const Vec3& b, const Vec3& c, double least) {
  const double area = doubledArea(a, b, c);
  double longest = 0;
  for (const auto& [p, q] : {std::pair{&a, &b}, std::pair{&b, &c}, std::pair{&c, &a}}) {
    const double dx = double((*q)[0]) - (*p)[0], dy = double((*q)[1]) - (*p)[1];
    longest = std::max(longest, dx * dx + dy * dy);
  }
  return area > 0 && area * area >= least * least * longest;
}

// A point strictly inside triangle t, rounded to float, or nothing when one
// of its three triangles would keep less than 1/100 of t's area or
// `least_area`, or be thinner than `least_width`.
std::optional<Vec3> splitPoint(const SubdivisionSpec& spec, const std::vector<Vec3>& v,
                               const Tri& t, double least_width, double least_area,
                               SeededRandom& rnd) {
  const Vec3 &a = v[t[0]], &b = v[t[1]], &c = v[t[2]];
  double w[3], sum = 0;
  for (double& x : w) sum += (x = rnd.range(0.05, 1.0));
  double p[2];
  for (int k = 0; k < 2; ++k) p[k] = (w[0] * a[k] + w[1] * b[k] + w[2] * c[k]) / sum;
  const Vec3 q = toFloat(p[0], p[1], spec.center[2] + spec.relief * rnd.unit());
  const double least = std::max(doubledArea(a, b, c) / 100, least_area);
  if (!(doubledArea(a, b, q) >= least && doubledArea(b, c, q) >= least &&
        doubledArea(c, a, q) >= least && least > 0))
    return std::nullopt;
  if (!thickEnough(a, b, q, least_width) || !thickEnough(b, c, q, least_width) ||
      !thickEnough(c, a, q, least_width))
    return std::nullopt;
  return q;
}

}  // namespace

Result<void> makeSubdivision(const SubdivisionSpec& spec, Geometry& out) {
  if (spec.triangles < 2 || spec.triangles % 2)
    return errorMessage(
        "a subdivision has an even number of triangles, at least 2 (the "
        "rectangle's two, then two more a split), not " +
        std::to_string(spec.triangles));
  out.kind = Geometry::Kind::Triangles;
  out.vertices.clear();
  out.indices.clear();
  const double x0 = spec.center[0] - spec.size[0] / 2, x1 = spec.center[0] + spec.size[0] / 2;
  const double y0 = spec.center[1] - spec.size[1] / 2, y1 = spec.center[1] + spec.size[1] / 2;
  const double z = spec.center[2];
  out.vertices = {toFloat(x0, y0, z), toFloat(x1, y0, z), toFloat(x1, y1, z), toFloat(x0, y1, z)};
  std::vector<Tri> tris = {{0, 1, 2}, {0, 2, 3}};
  // Four float steps at the rectangle's largest coordinate: an aim point
  // rounded to float (half a step) stays inside the triangles it aims at.
  const auto far =
      static_cast<float>(std::max({std::fabs(x0), std::fabs(x1), std::fabs(y0), std::fabs(y1)}));
  const double least_width = 4 * (double(std::nextafter(far, INFINITY)) - far);
  // A 64th of the mean (doubled) area: no triangle so thin that a float
  // device may take it as degenerate (model/watertight.h) for a ray that
  // crosses it.
  const double least_area = 2 * spec.size[0] * spec.size[1] / spec.triangles / 64;
  SeededRandom rnd(spec.seed);
  uint64_t refused = 0;
  const uint64_t most_refused = 64ull * spec.triangles + 1024;
  while (tris.size() < spec.triangles) {
    const size_t k = rnd.next() % tris.size();
    const Tri t = tris[k];
    const std::optional<Vec3> p = splitPoint(spec, out.vertices, t, least_width, least_area, rnd);
    if (!p) {
      if (++refused > most_refused)
        return errorMessage("the rectangle is too small for " + std::to_string(spec.triangles) +
                            " triangles at its coordinates: " + std::to_string(tris.size()) +
                            " made, the rest would fold or vanish in float");
      continue;
    }
    const auto n = static_cast<uint32_t>(out.vertices.size());
    out.vertices.push_back(*p);
    tris[k] = {t[0], t[1], n};
    tris.push_back({t[1], t[2], n});
    tris.push_back({t[2], t[0], n});
  }
  for (const Tri& t : tris) out.indices.insert(out.indices.end(), t.begin(), t.end());
  return {};
}

}  // namespace rayspec
