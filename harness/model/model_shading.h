// Model counterparts of shaders/lights.glsl and shaders/sphere.glsl: the same
// formulas, operation by operation, in float.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "base/vec3.h"
#include "model/model_program.h"

namespace rayspec {

using F4 = std::array<float, 4>;

// `light: point|spot|directional`: P = call.position, N = call.normal,
// record = the callable's shader record words (floats as bits).
F4 lightColor(const std::string& kind, const Vec3& P, const Vec3& N,
              const std::vector<uint32_t>& record);
F4 lightColor(LightKind kind, const Vec3& P, const Vec3& N, const std::vector<uint32_t>& record);

struct SphereRoots {
  bool hit = false;
  float t_near = 0, t_far = 0;
  float disc = 0;  // b * b - a * cc, as the float formula computes it
};
SphereRoots sphereRoots(const Vec3& bmin, const Vec3& bmax, const Vec3& o, const Vec3& d);

}  // namespace rayspec
