// The Embree scene of a case: one Embree scene per BLAS, instanced by a top
// scene (instance index = geometry ID there, geometry index = geometry ID in
// the BLAS scene). Triangles are Embree triangles, except in the exact tier
// and for triangles Embree would drop although Vulkan keeps them active (NaN
// in Y/Z only, coordinates beyond ~1.8e18): those become user geometry decided
// by the model's own test. AABBs are always user geometry.
#pragma once

#include <embree3/rtcore.h>

#include <array>
#include <unordered_map>
#include <vector>

#include "base/result.h"
#include "case/case.h"
#include "case/inactive.h"  // triangleInactive
#include "model/frame_error.h"
#include "model/model_engine.h"

namespace rayspec {

struct TraceState;  // model_trace.h

struct ModelGeometry {
  Geometry::Kind kind = Geometry::Kind::Triangles;
  uint32_t flags = 0;
  bool own_triangles = false;                  // user geometry with the model's test
  std::vector<std::array<Vec3, 3>> triangles;  // per primitive, geometry transform applied
                                               // (may be left empty: see buildModelScene)
  uint32_t count = 0;                          // primitives
  bool indexed = false;                        // indices given, every one in range
  std::vector<std::array<float, 6>> aabbs;
  // Triangles with NaN in Y or Z of a vertex (not X: inactive), undefined by
  // the specification: the object-space box where each might be (finite
  // coordinates' bounds, unbounded along a NaN component), by primitive.
  std::unordered_map<uint32_t, std::array<double, 6>> nan_regions;
  uint32_t blas = 0, index = 0;
  std::optional<Transform> transform;  // the geometry transform (case/share_frame.h)
  ModelTier tier = ModelTier::Exact;
  // Exact tier: how far a device's vertices may differ from `triangles` (a
  // geometry transform rounded in another order; zero without one), and the
  // candidate boxes' pad for rays through the BLAS's instances (their error
  // and the exact test's ambiguity zone: model/box_pad.h).
  DVec3 vertex_err{};
  double ray_pad = 0;
  // Exact tier, AABBs: how far the boxes are grown for Embree, so that every
  // box a device may offer a ray is enumerated (model/box_pad.h blasBoxPads).
  double box_pad = 0;
  // AABBs: tested as grown by their own extent on each side (a legal device:
  // ModelFaultSeam::aabbNeighboursRun); a ray that crosses only the grown box
  // runs its intersection program all the same.
  bool aabbs_grown = false;
};

struct ModelBlas {
  std::vector<ModelGeometry> geometries;
  bool triangles = false;
  RTCScene scene = nullptr;
};

struct ModelInstance {
  const Instance* src = nullptr;
  int blas = -1;                     // -1: inactive (null BLAS)
  std::array<double, 12> inverse{};  // world -> object, row-major 3x4
  std::array<float, 12> inverse_f{};
  InstanceForm form = InstanceForm::General;  // what a device's inverse rounds
};

struct ModelScene {
  ModelTier tier = ModelTier::Exact;
  bool filters = false;      // Embree triangles report every candidate to the model
  bool aabbs_grown = false;  // set before buildModelScene: ModelGeometry::aabbs_grown
  RTCDevice device = nullptr;
  // One Embree scene per top level (Scene::tlasCount()), each holding the
  // instances of that level under their index in Scene::instances.
  std::vector<RTCScene> tops;
  std::vector<ModelBlas> blases;
  std::vector<ModelInstance> instances;

  ModelScene() = default;
  ModelScene(const ModelScene&) = delete;
  ModelScene& operator=(const ModelScene&) = delete;
  ~ModelScene();
};

// Mask bits: instance masks use the low 8 bits; triangle geometries carry
// kMaskTriangles and AABB geometries kMaskAabbs, which a ray keeps unless it
// skips that kind.
constexpr unsigned kMaskTriangles = 0x100, kMaskAabbs = 0x200;

// Builds the scene. `filters`: every triangle candidate goes to the model
// (collect-then-process path); otherwise Embree's closest hit is used. A case
// with triangles of the model's own test turns filters on (s.filters): its
// traces take the collect-then-process path, which sees every triangle.
// `keep_triangles`: fill ModelGeometry::triangles even where nothing but the
// facing of a direct hit could read them (false: only where own triangle
// tests, candidates or an unindexed Embree buffer need them).
// An error only where Embree cannot make a device (out of memory).
Result<void> buildModelScene(ModelScene& s, const Case& c, ModelTier tier, bool filters,
                             bool keep_triangles = true);

// True when Embree would drop this triangle although Vulkan keeps it active.
bool needsOwnTriangleTest(const std::array<Vec3, 3>& tri);
// R-UB: an active triangle with NaN in Y or Z of a vertex. Its region: the
// box of its finite coordinates, unbounded along a component with a NaN,
// through the geometry transform (if any), conservatively.
bool triangleNanYZ(const std::array<Vec3, 3>& tri);
std::array<double, 6> nanTriangleRegion(const std::array<Vec3, 3>& tri,
                                        const std::optional<Transform>& transform);

}  // namespace rayspec
