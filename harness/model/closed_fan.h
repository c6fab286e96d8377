// R-WATERTIGHT: do the triangles a ray meets at one distance, near their
// edges, close around it? Only then is passing between them (missing them
// all) a leak; where they leave a side open (the outer border of a mesh, the
// vertex of an open fan, an edge whose other triangle was culled, masked or
// faces the other way), a miss is one of the legal answers.
//
// Vulkan, Ray Traversal, Watertightness: two triangles of one frame
// (case/share_frame.h) with the same winding share an edge (its two vertices bit identical, met in
// opposite order); a closed fan is three or more triangles around a shared
// vertex whose every edge at that vertex is shared by exactly two of them.
// The model asks in addition that the triangles face the ray alike: a fold
// (one triangle twice, in both windings) or a silhouette edge puts both on
// one side of the edge, and a watertight device may pass beside them both;
// that no edge near the ray is a border (no other triangle of the group has
// it: the error reaches past the mesh); and that none of them is degenerate
// (TriAmbiguity::Degenerate: nearly edge-on, a zero area a device culls).
#pragma once

#include <cstddef>
#include <vector>

#include "model/model_scene.h"
#include "model/model_trace_context.h"
#include "model/traversal.h"

namespace rayspec {

// Whether the triangle candidates `group` (indices into `cands`, met at one
// distance) of one frame (case/share_frame.h: one instance and geometry
// transform, or instances of the identity transform) close around the ray: where one
// of them is near a vertex (two of its edges within their bounds), a closed
// fan around that vertex; else an edge shared by two of them, one near it.
// A box among two or more counts as closing (boxes are decided together);
// a group of one never closes. `flags`: the trace's ray flags, for facing.
bool closesAroundRay(const ModelScene& scene, const std::vector<ModelCandidate>& cands,
                     const std::vector<size_t>& group, const TraceRay& ray, uint32_t flags);

}  // namespace rayspec
