#include <set>

#include "compare/compare_parts.h"
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

void compareAnyHitRuns(const Case& c, const Results& device, const Results& model, Verdict& v) {
  if (!allNoDuplicateTriangles(c) || device.records.size() != model.records.size()) return;
  const uint32_t words = recordWords();
  const uint32_t ahit = findRecordField("any_hit_runs")->offset, chit = findRecordField("closest_hit_runs")->offset,
                 isect = findRecordField("intersection_runs")->offset;
  std::set<uint32_t> ambiguous;
  for (const RayAmbiguity& a : model.ambiguous) ambiguous.insert(a.ray);
  FindingBuilder b;
  b.finding = {Status::Fail, "R-AHIT-DUP",
               "any-hit ran more often than once per primitive the ray crosses (NO_DUPLICATE_ANY_HIT_INVOCATION)"};
  size_t checked = 0;
  for (size_t i = 0; i < device.records.size() / words; ++i) {
    const uint32_t* d = &device.records[i * words];
    const uint32_t* m = &model.records[i * words];
    if (ambiguous.count(static_cast<uint32_t>(i)) || m[chit] != 0 || m[isect] != 0) continue;
    ++checked;
    if (d[ahit] > m[ahit]) b.addRay(static_cast<uint32_t>(i));
  }
  if (b.finding.ray_count) {
    b.finding.message += " on " + std::to_string(b.finding.ray_count) + " of " + std::to_string(checked) + " rays";
    b.flush(v);
  } else if (checked) {
    v.add({Status::Pass, "R-AHIT-DUP",
           "any_hit_runs at most once per crossed primitive on " + std::to_string(checked) + " rays", {}, 0});
  }
}

}  // namespace rayspec
