// R-WATERTIGHT: does an ambiguous ray cross an edge shared by two triangles,
// or a vertex closed all around by a fan of triangles? Only then is a miss a
// leak; on the outer border of a mesh a miss is a legal answer.
#pragma once

#include "case/case.h"
#include "results/results.h"

namespace rayspec {

// From the case's geometry: the ray's hit candidates of one frame
// (case/share_frame.h) that contain a common edge (reason "edge": the edge belongs to two
// of them) or a common vertex (reason "vertex": every edge of the candidates
// at that vertex belongs to two of them).
bool crossesSharedEdge(const Case& c, const RayAmbiguity& a);

// The ray crosses only the outer border of a mesh: its hit candidates are one
// triangle (reason "edge") or triangles around a common vertex whose fan is
// open (reason "vertex"). Whether such a ray hits is not specified: a miss
// is legal whatever the candidate list says.
bool crossesBorderOnly(const Case& c, const RayAmbiguity& a);

// A ray through two or more triangles that share the crossed edge or close a
// fan around the crossed vertex (its shared_triangles, crossesSharedEdge):
// how many there are and how many of them the model counted as hits (where
// any-hit ignored them, the model ran it that often; a watertight device
// runs it once). `triangles` is 0 when the ray is no such ray, or the model
// hit none of them.
struct SharedCrossing {
  uint32_t triangles = 0, model_hits = 0;
};
SharedCrossing sharedCrossing(const Case& c, const RayAmbiguity& a);

// sharedCrossing where the model's any-hit ran for each shared triangle it
// decided as a hit (model_any_hit_runs at least model_hits): only there do
// any-hit runs of a device beyond the model's tell a double hit. Empty where
// those triangles ran none (opaque, or a hit group without any-hit): there
// a device's extra run is on another candidate (a tie with another
// instance, whose triangles share no edge with these).
SharedCrossing anyHitCrossing(const Case& c, const RayAmbiguity& a, uint32_t model_any_hit_runs);

}  // namespace rayspec
