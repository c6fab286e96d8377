// The `aim` form of a case's `rays`: rays aimed at the interior features of
// one triangle mesh of the scene (where floating point decides), so that
// every ray crosses the mesh strictly inside its outline.
#pragma once

#include "base/result.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "case/case.h"

namespace rayspec {

// What a ray of the `aim` form is aimed at: a vertex closed all around, a
// point of an edge two triangles share, or a triangle's centroid.
#define RAYSPEC_AIM_FEATURES(X) X(Vertex, "vertex") X(Edge, "edge") X(Face, "centroid")
enum class AimFeature { RAYSPEC_AIM_FEATURES(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(AimFeature, RAYSPEC_AIM_FEATURES);
struct AimTarget {
  AimFeature feature = AimFeature::Face;
  uint32_t instance = 0, geometry = 0;
  std::vector<uint32_t> primitives;  // the triangles that have the feature (a centroid: its own)
  std::array<double, 3> object{}, world{};  // the aim point, and it through the transforms
};

struct AimSpec {
  uint32_t instance = 0, geometry = 0;
  bool vertices = true, edges = true, faces = true;  // which features to aim at
  uint32_t edge_points = 1;                          // points per edge, at k / (edge_points + 1)
  std::array<double, 3> offset{0, 0, 1};             // world origin = aim point + offset
  double direction_scale = 1;                        // world direction = -offset * direction_scale
  uint32_t every = 1;  // only each every-th point of each feature, from the first (large meshes)
};

// The interior features of a triangle mesh, in object space (double):
// vertices closed all around (every edge at them shared by exactly two
// triangles), points on edges shared by exactly two triangles, and triangle
// centroids; in that order, each list in the order of first appearance.
// Vertices are told apart by position. Triangles with a NaN are left out.
std::vector<std::array<double, 3>> meshAimPoints(const Geometry& g, const AimSpec& spec);
// The same points, each with its feature and the triangles that have it
// (instance, geometry and world point left for aimRays).
std::vector<AimTarget> meshAimTargets(const Geometry& g, const AimSpec& spec);

// One ray per aim point (the other fields from `defaults`): the aim point
// through the geometry's and the instance's transforms (in double) plus
// `offset`, rounded to float, towards the point. An error when the instance
// or geometry is not a triangle mesh of the scene or the mesh has no
// interior feature. *targets (when given) gets what each ray is aimed at.
Result<std::vector<Ray>> aimRays(const Scene& scene, const AimSpec& spec, const Ray& defaults,
                                 std::vector<AimTarget>* targets = nullptr);

}  // namespace rayspec
