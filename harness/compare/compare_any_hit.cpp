#include <algorithm>
#include <map>
#include <optional>

#include "compare/compare_parts.h"
#include "compare/finding_rules.h"
#include "compare/shared_edge.h"
#include "program/walk_program.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// Every geometry of the scene is triangles with NO_DUPLICATE_ANY_HIT_INVOCATION.
bool allNoDuplicateTriangles(const Case& c) {
  bool any = false;
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries) {
      if (g.kind != Geometry::Kind::Triangles || !(g.flags & kGeometryNoDuplicateAnyHit))
        return false;
      any = true;
    }
  return any;
}

// The scene has geometry, and all of it triangles.
bool allTriangles(const Case& c) {
  bool any = false;
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries) {
      if (g.kind != Geometry::Kind::Triangles) return false;
      any = true;
    }
  return any;
}

// Some any-hit may call terminateRayEXT (in a function it invokes too).
bool anyHitMayTerminate(const Case& c) {
  bool terminates = false;
  for (const HitGroup& g : c.pipeline.hit_groups)
    if (g.any_hit)
      walkStatements(*g.any_hit, [&](const Stmt& s) {
        terminates = terminates || s.kind == Stmt::Kind::Terminate;
      });
  return terminates;
}

// The rule an any-hit count off the primitives a clear ray crosses names:
// `own`, and R-AS-SIZE where the case claims it (a build that lost a
// primitive runs one any-hit fewer there, one that kept it twice one more).
FindingRule primitiveRunsRule(const Case& c, const std::string& own) {
  return findingRule({own, "R-AS-SIZE"}, c.rules, own);
}

// R-AHIT-CLOSEST: on a clear ray through triangles, the model runs any-hit
// exactly for the candidates every device must show it: those no nearer hit
// was accepted before (in t order: every ignored one, and the one accepted).
// Another order or a duplicate invocation only adds runs; not so where an
// any-hit may terminate, which ends traversal before nearer candidates a
// far-to-near order has not reached yet.
void compareAnyHitMinimum(const Case& c, const Results& device, const Results& model,
                          const std::set<uint32_t>& skip, Verdict& v) {
  const uint32_t words = recordWords(), ahit = findRecordField("any_hit_runs")->offset;
  FindingBuilder b;
  b.finding = findingOf(Status::Fail, primitiveRunsRule(c, "R-AHIT-CLOSEST"),
                        "any-hit ran fewer times than the candidates every device must show it "
                        "(the nearer ignored ones and the closest hit's)");
  for (size_t i = 0; i < device.records.size() / words; ++i)
    if (!skip.count(static_cast<uint32_t>(i)) &&
        device.records[i * words + ahit] < model.records[i * words + ahit])
      b.addRay(static_cast<uint32_t>(i));
  b.flush(v);
}

size_t primitiveCount(const Geometry& g) {
  if (g.kind == Geometry::Kind::Aabbs) return g.aabbs.size();
  return (g.indices.empty() ? g.vertices.size() : g.indices.size()) / 3;
}

// The any_hit_slots bits (results/record_layout.h) a repeat in which breaks
// R-AHIT-DUP: each held by exactly one primitive of the scene, and that one
// in a NO_DUPLICATE_ANY_HIT_INVOCATION geometry. AABBs count only where no
// intersection program reports more than once (each report may run any-hit).
uint32_t noDuplicateSlots(const Case& c) {
  size_t reports = 0;
  for (const HitGroup& g : c.pipeline.hit_groups)
    if (g.intersection) {
      size_t n = 0;
      walkStatements(*g.intersection, [&](const Stmt& s) { n += s.kind == Stmt::Kind::Report; });
      reports = std::max(reports, n);
    }
  uint32_t held = 0, shared = 0, no_dup = 0;
  for (size_t i = 0; i < c.scene.instances.size(); ++i) {
    const Instance& inst = c.scene.instances[i];
    if (!inst.blas) continue;
    const Blas& b = c.scene.blases[*inst.blas];
    for (size_t g = 0; g < b.geometries.size(); ++g) {
      const Geometry& geo = b.geometries[g];
      const bool judged = (geo.flags & kGeometryNoDuplicateAnyHit) &&
                          (geo.kind == Geometry::Kind::Triangles || reports <= 1);
      for (size_t p = 0; p < primitiveCount(geo); ++p) {
        const uint32_t bit = 1u << anyHitSlot(static_cast<uint32_t>(i), static_cast<uint32_t>(g),
                                              static_cast<uint32_t>(p));
        if (held & bit) shared |= bit;
        held |= bit;
        if (judged)
          no_dup |= bit;
        else
          shared |= bit;
      }
    }
  }
  return no_dup & ~shared;
}

// R-AHIT-DUP per primitive: on a launch ray of one trace, any-hit never runs
// twice on a primitive of a NO_DUPLICATE_ANY_HIT_INVOCATION geometry, whatever
// the answer (ambiguous rays too).
void compareAnyHitRepeats(const Case& c, const Results& device, const std::set<uint32_t>& undefined,
                          Verdict& v) {
  const uint32_t slots = noDuplicateSlots(c);
  if (!slots || !traceShape(c).single_trace) return;
  const uint32_t words = recordWords(), repeats = findRecordField("any_hit_repeats")->offset;
  FindingBuilder b;
  b.finding = {Status::Fail, "R-AHIT-DUP",
               "any-hit ran twice on one primitive of a NO_DUPLICATE_ANY_HIT_INVOCATION geometry"};
  size_t rays = 0;
  for (size_t i = 0; i < device.records.size() / words; ++i) {
    if (undefined.count(static_cast<uint32_t>(i))) continue;
    ++rays;
    if (device.records[i * words + repeats] & slots) b.addRay(static_cast<uint32_t>(i));
  }
  if (b.finding.ray_count)
    b.flush(v);
  else if (rays)
    v.add({Status::Pass,
           "R-AHIT-DUP",
           "any-hit ran at most once per NO_DUPLICATE_ANY_HIT_INVOCATION primitive on " +
               std::to_string(rays) + " rays",
           {},
           0});
}

}  // namespace

std::optional<uint32_t> watertightAnyHitLimit(const Case& c, const RayAmbiguity& a,
                                              const uint32_t* m) {
  if (!allNoDuplicateTriangles(c) || fieldWord(m, "closest_hit_runs") != 0 ||
      fieldWord(m, "intersection_runs") != 0)
    return std::nullopt;
  const uint32_t runs = fieldWord(m, "any_hit_runs");
  const SharedCrossing s = anyHitCrossing(c, a, runs);
  if (!s.triangles) return std::nullopt;
  return runs + 1 - s.model_hits;
}

void compareAnyHitRuns(const Case& c, const Results& device, const Results& model,
                       const std::set<uint32_t>& undefined, Verdict& v) {
  if (device.records.size() != model.records.size()) return;
  compareAnyHitRepeats(c, device, undefined, v);
  if (allTriangles(c) && !anyHitMayTerminate(c)) {
    std::set<uint32_t> skip = undefined;
    for (const RayAmbiguity& a : model.ambiguous) skip.insert(a.ray);
    compareAnyHitMinimum(c, device, model, skip, v);
  }
  if (!allNoDuplicateTriangles(c)) return;
  const uint32_t words = recordWords();
  const uint32_t ahit = findRecordField("any_hit_runs")->offset,
                 chit = findRecordField("closest_hit_runs")->offset,
                 isect = findRecordField("intersection_runs")->offset;
  const auto ambiguous = ambiguityByRay(model);
  FindingBuilder doubled;
  doubled.finding = {Status::QualityWarning, "R-WATERTIGHT", kAnyHitDoubleHit};
  FindingBuilder b;
  b.finding = findingOf(Status::Fail, primitiveRunsRule(c, "R-AHIT-DUP"),
                        "any-hit ran more often than once per primitive the ray crosses "
                        "(NO_DUPLICATE_ANY_HIT_INVOCATION)");
  size_t checked = 0;
  for (size_t i = 0; i < device.records.size() / words; ++i) {
    const uint32_t* d = &device.records[i * words];
    const uint32_t* m = &model.records[i * words];
    if (m[chit] != 0 || m[isect] != 0 || undefined.count(static_cast<uint32_t>(i))) continue;
    if (const auto it = ambiguous.find(static_cast<uint32_t>(i)); it != ambiguous.end()) {
      const std::optional<uint32_t> most = watertightAnyHitLimit(c, *it->second, m);
      if (most && d[ahit] > *most) doubled.addRay(static_cast<uint32_t>(i));
      continue;
    }
    ++checked;
    if (d[ahit] > m[ahit]) b.addRay(static_cast<uint32_t>(i));
  }
  doubled.flush(v);
  if (b.finding.ray_count) {
    b.finding.message +=
        " on " + std::to_string(b.finding.ray_count) + " of " + std::to_string(checked) + " rays";
    b.flush(v);
  } else if (checked) {
    v.add(
        {Status::Pass,
         "R-AHIT-DUP",
         "any_hit_runs at most once per crossed primitive on " + std::to_string(checked) + " rays",
         {},
         0});
  }
}

}  // namespace rayspec
