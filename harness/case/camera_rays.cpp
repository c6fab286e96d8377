// Camera and grid launch rays.
#include "case/camera_rays.h"

#include <cmath>

#include "base/vec3.h"

namespace rayspec {

std::vector<Ray> cameraRays(const CameraSpec& cam, const Ray& defaults) {
  DVec3 forward = sub(cam.look_at, cam.origin);
  const double flen = length(forward);
  if (!(flen > 0)) return {};
  forward = scaled(forward, 1 / flen);
  DVec3 right = cross(forward, cam.up);
  const double rlen = length(right);
  if (!(rlen > 1e-12)) return {};
  right = scaled(right, 1 / rlen);
  const DVec3 up = cross(right, forward);
  const double half_h = std::tan(cam.fov_degrees * M_PI / 360.0);
  const double half_w = half_h * cam.width / cam.height;

  std::vector<Ray> rays;
  rays.reserve(size_t(cam.width) * cam.height);
  for (uint32_t y = 0; y < cam.height; ++y) {
    const double v = (1 - 2 * (y + 0.5) / cam.height) * half_h;  // +1 at the top
    for (uint32_t x = 0; x < cam.width; ++x) {
      const double u = (2 * (x + 0.5) / cam.width - 1) * half_w;
      DVec3 d;
      for (int i = 0; i < 3; ++i) d[i] = forward[i] + u * right[i] + v * up[i];
      Ray r = defaults;
      r.origin = toFloat(cam.origin);
      r.direction = toFloat(scaled(d, 1 / length(d)));
      rays.push_back(r);
    }
  }
  return rays;
}

std::vector<Ray> gridRays(const GridSpec& g, const Ray& defaults) {
  std::vector<Ray> rays;
  rays.reserve(size_t(g.width) * g.height);
  for (uint32_t y = 0; y < g.height; ++y)
    for (uint32_t x = 0; x < g.width; ++x) {
      DVec3 o;
      for (int i = 0; i < 3; ++i) o[i] = g.origin[i] + (x + 0.5) * g.du[i] + (y + 0.5) * g.dv[i];
      Ray r = defaults;
      r.origin = toFloat(o);
      r.direction = toFloat(g.direction);
      rays.push_back(r);
    }
  return rays;
}

}  // namespace rayspec
