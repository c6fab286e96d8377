#include "model/model_shading.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace rayspec {
namespace {

float recordFloat(const std::vector<uint32_t>& r, uint32_t i) {
  return std::bit_cast<float>(i < r.size() ? r[i] : 0u);
}
float dot3(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 sub3(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 div3(const Vec3& a, float s) {
  return {a[0] / s, a[1] / s, a[2] / s};
}
Vec3 normalize3(const Vec3& v) {
  return div3(v, std::sqrt(dot3(v, v)));
}

}  // namespace

F4 lightColor(const std::string& kind, const Vec3& position, const Vec3& normal,
              const std::vector<uint32_t>& rec) {
  return lightColor(kind == "point"  ? LightKind::Point
                    : kind == "spot" ? LightKind::Spot
                                     : LightKind::Directional,
                    position, normal, rec);
}

F4 lightColor(LightKind kind, const Vec3& position, const Vec3& normal,
              const std::vector<uint32_t>& rec) {
  auto f = [&](uint32_t i) {
    return recordFloat(rec, i);
  };
  if (kind == LightKind::Point) {
    const Vec3 to_light = sub3({f(0), f(1), f(2)}, position);
    const float d2 = dot3(to_light, to_light);
    const Vec3 l = div3(to_light, std::sqrt(d2));
    const float k = std::max(dot3(normal, l), 0.0f) / d2;
    return {k * f(3), k * f(4), k * f(5), 1.0f};
  }
  if (kind == LightKind::Spot) {
    const Vec3 to_light = sub3({f(0), f(1), f(2)}, position);
    const float d = std::sqrt(dot3(to_light, to_light));
    const Vec3 l = div3(to_light, d);
    const Vec3 nl = {-l[0], -l[1], -l[2]};
    const float cosang = dot3(nl, normalize3({f(3), f(4), f(5)}));
    const float s = std::clamp((cosang - f(7)) / (f(6) - f(7)), 0.0f, 1.0f);  // the smooth cone
    const float c = s * std::max(dot3(normal, l), 0.0f) / (d * d);
    return {c, c, c, 1.0f};
  }
  // directional
  const Vec3 n = normalize3({f(0), f(1), f(2)});
  const Vec3 l = {-n[0], -n[1], -n[2]};
  const float k = std::max(dot3(normal, l), 0.0f);
  return {k * f(3), k * f(4), k * f(5), 1.0f};
}

SphereRoots sphereRoots(const Vec3& bmin, const Vec3& bmax, const Vec3& o, const Vec3& d) {
  Vec3 c, h;
  for (int k = 0; k < 3; ++k) {
    c[k] = (bmin[k] + bmax[k]) * 0.5f;
    h[k] = (bmax[k] - bmin[k]) * 0.5f;
  }
  const float r = std::min(std::min(h[0], h[1]), h[2]);
  const Vec3 oc = sub3(o, c);
  const float a = dot3(d, d);
  const float b = dot3(oc, d);
  const float cc = dot3(oc, oc) - r * r;
  const float disc = b * b - a * cc;
  const float s = std::sqrt(std::max(disc, 0.0f));
  SphereRoots sp;
  sp.hit = disc >= 0.0f;
  sp.disc = disc;
  sp.t_near = (-b - s) / a;
  sp.t_far = (-b + s) / a;
  return sp;
}

}  // namespace rayspec
