// What Embree's callbacks hand to the model during one traversal: every
// candidate of the trace is collected here and decided later, in order.
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <limits>
#include <vector>

#include "model/watertight.h"

namespace rayspec {

struct ModelScene;

struct ModelCandidate {
  double t = 0;  // triangles: hit t; AABBs: box entry, clamped to tmin
  uint32_t instance = 0, geometry = 0, primitive = 0;
  bool aabb = false;
  bool hit = true;  // triangles: the model's decision (false: kept only as ambiguous)
  float b1 = 0, b2 = 0;
  TriAmbiguity ambiguity = TriAmbiguity::None;
  uint8_t near_edges = 0;  // triangles, exact tier: WatertightHit::near_edges
  bool near_face = false;  // AABBs, exact tier: the ray passes within the error
                           // bound of a face (a device may or may not see it)
  // AABBs, exact tier: the model's ray misses the box, by no more than that
  // bound (near_face too): a device may offer it; the model does not (its
  // what-if runs do, and a legal device offering every such box).
  bool outside = false;
  // AABBs: the model's own ray misses the box (outside, or met only as grown
  // by ModelFaultSeam::aabbNeighboursRun): only a legal device with a
  // conservative AABB test (R-AABB-CONS) runs its program.
  bool missed = false;
  // Triangles, exact tier: the ray's line lies in the triangle's plane (to
  // rounding, in_plane.h): no hit of the model's, a device's hit anywhere in
  // [t - t_err, t + t_err] (the line across the triangle, within the
  // trace's interval).
  bool in_plane = false;
  // AABBs, exact tier: where the ray is inside the box shrunk by the
  // device's error bound (every device enters the box there); empty (NaN)
  // where it grazes a face or in other tiers (model/counter_floors.cpp).
  double inner_t0 = std::numeric_limits<double>::quiet_NaN();
  double inner_t1 = std::numeric_limits<double>::quiet_NaN();
  // Triangles, exact tier: every device compares t with the trace's tmin /
  // tmax exactly (model/exact_interval.h): no tie at that end.
  bool exact_tmin = false, exact_tmax = false;
  double t_err = 0;           // triangles, exact tier: how far a device's t may lie (0: unknown)
  bool nan_triangle = false;  // a triangle with NaN in Y or Z (never a hit: the
                              // ray crosses where it might be, R-UB); t: entry
};

struct TraceContext {
  RTCIntersectContext rtc;  // first member: Embree hands back its address
  const ModelScene* scene = nullptr;
  DVec3 origin{}, direction{};  // world ray
  double tmin = 0, tmax = 0;
  std::vector<ModelCandidate>* candidates = nullptr;
  // The model's own triangle tests (model_scene.cpp): what depends only on
  // (ray, instance), for the instance seen last (Embree visits one
  // instance's primitives together): the object-space ray with the device's
  // frame error (exact tier; none otherwise) and its watertight part, and
  // whether every device derives the same object-space ray
  // (model/exact_interval.h).
  uint32_t object_instance = UINT32_MAX;  // UINT32_MAX: none yet
  WatertightRay object_ray;
  bool object_exact = false;
};

}  // namespace rayspec
