// A huge ray at a sphere-testing box: a launch ray whose object-space origin
// lies kHugeRayDistance or more from a box whose intersection program tests
// the sphere inscribed in it (sphere_hit, sphere_near, sphere_far). A device
// rounds the ray's object-space origin once (gl_ObjectRayOriginEXT: the
// world-to-object transform, in float), and that far away one rounding
// moves it by a sizeable part of the box: several of the program's decisions
// (the discriminant's sign, each root against ray_tmin and the other) flip
// together and its roots move by more than R-PREC allows, so no legal set
// of answers can be listed to judge the ray by (NVIDIA 580.159.04, fuzz
// seeds 120464 and 120531: rays 2.5e5 to 8e6 away). The one definition of
// both of its users:
//   the fuzz generator (fuzz/generate_aim.cpp) draws a huge ray (origins
//     kHugeRayReach x a direction of 0.25 or longer from their target) only
//     where no active instance holds boxes, every box program it writes
//     testing its sphere;
//   the portability check (mutate/case_portability.h) refuses a case with one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "case/case.h"

namespace rayspec {

// From this distance on (object space: where the rounding happens) a ray is huge.
constexpr double kHugeRayDistance = 1e4;
// The generator's far rays start reach x d from their target, reach a
// multiple of this, d 0.25 long or longer: every one of them is huge.
constexpr double kHugeRayReach = 1e5;
static_assert(kHugeRayReach * 0.25 / 2 >= kHugeRayDistance,
              "a generated far ray is huge in the object space of an instance that scales by 2");

// Whether the program reads sphere_hit, sphere_near or sphere_far.
bool testsInscribedSphere(const Program& p);

struct HugeSphereRay {
  size_t ray = 0;          // the launch ray
  uint32_t instance = 0;   // whose box it meets
  uint32_t geometry = 0;   // of the instance's BLAS
  uint32_t primitive = 0;  // the box
  // The hit group whose intersection program tests the sphere; none: a ray
  // query's aabb block does (of any stage: sphere_hit there reads the
  // candidate's box and object-space ray).
  std::optional<size_t> hit_group;
  double distance = 0;  // from the object-space origin to the box
};

// The first huge ray of `c` at a sphere-testing box: a launch ray (not
// skipping boxes, its cull mask meeting the instance's) whose interval
// passes within a box's own extent of a box of an active instance, whose hit
// group (the instance's SBT offset + the ray's + geometry x the ray's
// stride) tests the sphere, or any box where a ray query's aabb block does,
// from kHugeRayDistance or more away; nullopt: none.
std::optional<HugeSphereRay> hugeRayAtSphereBox(const Case& c);

}  // namespace rayspec
