#include <map>

#include "compare/compare_parts.h"
#include "compare/shared_edge.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// Every geometry of the scene is triangles with NO_DUPLICATE_ANY_HIT_INVOCATION.
bool allNoDuplicateTriangles(const Case& c) {
  bool any = false;
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries) {
      if (g.kind != Geometry::Kind::Triangles || !(g.flags & kGeometryNoDuplicateAnyHit)) return false;
      any = true;
    }
  return any;
}

}  // namespace

void compareAnyHitRuns(const Case& c, const Results& device, const Results& model,
                       const std::set<uint32_t>& undefined, Verdict& v) {
  if (!allNoDuplicateTriangles(c) || device.records.size() != model.records.size()) return;
  const uint32_t words = recordWords();
  const uint32_t ahit = findRecordField("any_hit_runs")->offset, chit = findRecordField("closest_hit_runs")->offset,
                 isect = findRecordField("intersection_runs")->offset;
  std::map<uint32_t, const RayAmbiguity*> ambiguous;
  for (const RayAmbiguity& a : model.ambiguous) ambiguous[a.ray] = &a;
  // A double hit (R-WATERTIGHT, a "should"): on a ray through a shared edge
  // or vertex whose candidates were all ignored, the model ran any-hit once
  // for each of the h triangles sharing it that it decided as hits (one
  // where the mesh is closed); a watertight device runs it for one of them,
  // so at most (model - (h - 1)) times in all.
  FindingBuilder doubled;
  doubled.finding = {Status::QualityWarning, "R-WATERTIGHT",
                     "double hit: any-hit ran for more than one of the triangles sharing an edge or vertex"};
  FindingBuilder b;
  b.finding = {Status::Fail, "R-AHIT-DUP",
               "any-hit ran more often than once per primitive the ray crosses (NO_DUPLICATE_ANY_HIT_INVOCATION)"};
  size_t checked = 0;
  for (size_t i = 0; i < device.records.size() / words; ++i) {
    const uint32_t* d = &device.records[i * words];
    const uint32_t* m = &model.records[i * words];
    if (m[chit] != 0 || m[isect] != 0 || undefined.count(static_cast<uint32_t>(i))) continue;
    if (const auto it = ambiguous.find(static_cast<uint32_t>(i)); it != ambiguous.end()) {
      // Only where the triangles really share the edge, or close a fan around
      // the vertex: on the outer border of a mesh hitting two is no rule's break.
      const SharedCrossing s = sharedCrossing(c, *it->second);
      if (s.triangles && d[ahit] + s.model_hits > m[ahit] + 1) doubled.addRay(static_cast<uint32_t>(i));
      continue;
    }
    ++checked;
    if (d[ahit] > m[ahit]) b.addRay(static_cast<uint32_t>(i));
  }
  doubled.flush(v);
  if (b.finding.ray_count) {
    b.finding.message += " on " + std::to_string(b.finding.ray_count) + " of " + std::to_string(checked) + " rays";
    b.flush(v);
  } else if (checked) {
    v.add({Status::Pass, "R-AHIT-DUP",
           "any_hit_runs at most once per crossed primitive on " + std::to_string(checked) + " rays", {}, 0});
  }
}

}  // namespace rayspec
