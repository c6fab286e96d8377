// The launch rays of the `camera` and `grid` forms of a case's `rays`.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "case/case.h"

namespace rayspec {

// Perspective pinhole camera: one ray per pixel centre, fov is the vertical
// field of view in degrees, row 0 is the top of the image. Directions are
// unit length; computed in double, stored as float.
struct CameraSpec {
  uint32_t width = 1, height = 1;
  std::array<double, 3> origin{0, 0, 0}, look_at{0, 0, -1}, up{0, 1, 0};
  double fov_degrees = 60;
};

// Ray (x, y) starts at origin + (x + 0.5) du + (y + 0.5) dv, with `direction`.
struct GridSpec {
  uint32_t width = 1, height = 1;
  std::array<double, 3> origin{0, 0, 0}, du{1, 0, 0}, dv{0, 1, 0}, direction{0, 0, -1};
};

// Rays in row-major order (index = y * width + x); all other ray fields come
// from `defaults`. cameraRays returns empty when the camera is degenerate
// (look_at == origin, or up parallel to the view direction).
std::vector<Ray> cameraRays(const CameraSpec& cam, const Ray& defaults);
std::vector<Ray> gridRays(const GridSpec& grid, const Ray& defaults);

}  // namespace rayspec
