// Record edits of run counts and hits: which stages ran on a ray.
#include <sstream>

#include "compare/shared_edge.h"
#include "fault/fault_impl.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// A ray the model found clear, on which pred holds.
template <typename Pred>
bool findClear(const RecordFaultArgs& a, Pred pred, uint32_t* out) {
  for (uint32_t ray = 0; ray < a.dev.rays(); ++ray) {
    if (a.ambiguous.count(ray) || !pred(ray)) continue;
    *out = ray;
    return true;
  }
  return false;
}

std::string counterNote(const std::string& counter, int delta) {
  if (counter.empty()) return "";
  return ", counter '" + counter + "' " + (delta < 0 ? "- " : "+ ") +
         std::to_string(std::abs(delta));
}

// A ray through a shared edge or vertex (the model marks it ambiguous) whose
// candidates any-hit ignored: the model ran any-hit for each of the
// triangles sharing it that it decided as hits. Empty when not such a ray.
SharedCrossing sharedEdgeAnyHitRay(const RecordFaultArgs& a, const RayAmbiguity& amb) {
  if (amb.ray >= a.dev.rays()) return {};
  const SharedCrossing s = anyHitCrossing(a.c, amb, a.mod.get(amb.ray, "any_hit_runs"));
  if (!s.triangles || a.mod.get(amb.ray, "closest_hit_runs") != 0 ||
      a.mod.get(amb.ray, "intersection_runs") != 0)
    return {};
  return s;
}

}  // namespace

FaultResult describeRay(uint32_t ray, const std::string& what) {
  std::ostringstream s;
  s << "ray " << ray << ": " << what;
  return {true, s.str()};
}

FaultResult notApplicable(const std::string& why) {
  return {false, why};
}

// R-STAGE-INTERFACE: a compiler that accepts every shader a case expects it
// to reject.
FaultResult stageInterfaceAccepted(RecordFaultArgs& a) {
  if (a.dev.w.rejected.empty()) return notApplicable("the case expects no rejection");
  const size_t n = a.dev.w.rejected.size();
  a.dev.w.rejected.clear();
  return {true, std::to_string(n) + " shader(s) the compiler must reject accepted"};
}

FaultResult dropMiss(RecordFaultArgs& a) {
  uint32_t ray;
  if (!findClear(
          a,
          [&](uint32_t r) {
            return a.dev.get(r, "miss_runs") >= 1 && a.mod.get(r, "miss_runs") >= 1;
          },
          &ray))
    return notApplicable("no clear ray ran a miss shader");
  const uint32_t before = a.dev.get(ray, "miss_runs");
  a.dev.set(ray, "miss_runs", 0);
  const std::string counter = a.dev.bumpCounter(missCounters(a.c), -1);
  return describeRay(ray,
                     "miss_runs " + std::to_string(before) + " -> 0" + counterNote(counter, -1));
}

FaultResult swapPrimitiveId(RecordFaultArgs& a) {
  RecordEdit& dev = a.dev;
  auto usable = [&](uint32_t r) {
    return !a.ambiguous.count(r) && dev.written(r, "primitive_id") &&
           dev.get(r, "closest_hit_runs") != 0;
  };
  for (uint32_t x = 0; x < dev.rays(); ++x) {
    if (!usable(x)) continue;
    for (uint32_t y = x + 1; y < dev.rays(); ++y) {
      if (!usable(y)) continue;
      const uint32_t px = dev.get(x, "primitive_id"), py = dev.get(y, "primitive_id");
      if (px == py) continue;
      dev.set(x, "primitive_id", py);
      dev.set(y, "primitive_id", px);
      return {true, "rays " + std::to_string(x) + " and " + std::to_string(y) + ": primitive ids " +
                        std::to_string(px) + " and " + std::to_string(py) + " swapped"};
    }
  }
  return notApplicable("no two clear hit rays with a recorded primitive_id that differs");
}

FaultResult chitAfterIgnore(RecordFaultArgs& a) {
  RecordEdit& dev = a.dev;
  uint32_t ray;
  auto missed = [&](uint32_t r) {
    return dev.get(r, "closest_hit_runs") == 0 && dev.get(r, "miss_runs") >= 1;
  };
  // Prefer a ray whose candidates any-hit ignored; else any ray that missed.
  if (!findClear(
          a, [&](uint32_t r) { return missed(r) && dev.get(r, "any_hit_runs") > 0; }, &ray) &&
      !findClear(a, missed, &ray))
    return notApplicable("no clear ray that missed");
  dev.set(ray, "closest_hit_runs", dev.get(ray, "closest_hit_runs") + 1);
  const std::string counter = dev.bumpCounter(closestHitCounters(a.c), +1);
  return describeRay(ray, "closest_hit_runs 0 -> 1 (any-hit ran " +
                              std::to_string(dev.get(ray, "any_hit_runs")) + " times)" +
                              counterNote(counter, +1));
}

FaultResult shiftT(RecordFaultArgs& a) {
  uint32_t ray;
  if (!findClear(
          a,
          [&](uint32_t r) {
            return a.dev.get(r, "closest_hit_runs") > 0 && a.dev.written(r, "hit_t");
          },
          &ray))
    return notApplicable("no clear hit ray with a recorded hit_t");
  const float t = a.dev.getFloat(ray, "hit_t");
  a.dev.setFloat(ray, "hit_t", t + 1e-3f);
  return describeRay(ray, "hit_t " + std::to_string(t) + " -> " + std::to_string(t + 1e-3f));
}

FaultResult duplicateAnyHit(RecordFaultArgs& a) {
  bool flagged = false;
  for (const Blas& b : a.c.scene.blases)
    for (const Geometry& g : b.geometries)
      flagged = flagged || (g.flags & kGeometryNoDuplicateAnyHit);
  if (!flagged) return notApplicable("no geometry has no_duplicate_any_hit");
  RecordEdit& dev = a.dev;
  uint32_t ray;
  // Prefer a ray whose candidates were all ignored (the model then ran any-hit
  // once on every primitive the ray crosses).
  if (!findClear(
          a,
          [&](uint32_t r) {
            return dev.get(r, "any_hit_runs") > 0 && a.mod.get(r, "closest_hit_runs") == 0;
          },
          &ray) &&
      !findClear(
          a, [&](uint32_t r) { return dev.get(r, "any_hit_runs") > 0; }, &ray))
    return notApplicable("no clear ray ran any-hit");
  // One more run, on primitives it ran on already (their any_hit_slots bits
  // now repeated too).
  const uint32_t before = dev.get(ray, "any_hit_runs");
  dev.set(ray, "any_hit_runs", before + 1);
  dev.set(ray, "any_hit_repeats", dev.get(ray, "any_hit_repeats") | dev.get(ray, "any_hit_slots"));
  const std::string counter = dev.bumpCounter(anyHitCounters(a.c), +1);
  return describeRay(ray, "any_hit_runs " + std::to_string(before) + " -> " +
                              std::to_string(before + 1) + ", its primitives repeated" +
                              counterNote(counter, +1));
}

// A leak: a ray through an edge or vertex misses every triangle there, where
// they share it, or where no legal answer is a miss (and not just the outer
// border of a mesh).
FaultResult leakEdge(RecordFaultArgs& a) {
  RecordEdit& dev = a.dev;
  for (const RayAmbiguity& amb : a.model.ambiguous) {
    if (amb.reason != AmbiguityReason::Edge && amb.reason != AmbiguityReason::Vertex) continue;
    bool miss_legal = false;
    for (const Candidate& k : amb.candidates) miss_legal = miss_legal || !k.hit;
    const bool leak = crossesSharedEdge(a.c, amb) || (!miss_legal && !crossesBorderOnly(a.c, amb));
    if (!leak || amb.ray >= dev.rays() || dev.get(amb.ray, "closest_hit_runs") == 0) continue;
    dev.set(amb.ray, "closest_hit_runs", 0);
    dev.set(amb.ray, "miss_runs", 1);
    if (dev.written(amb.ray, "hit")) dev.set(amb.ray, "hit", 0);
    dev.bumpCounter(closestHitCounters(a.c), -1);
    dev.bumpCounter(missCounters(a.c), +1);
    return describeRay(
        amb.ray, "on a shared " + std::string(ambiguityReasonName(amb.reason)) + ", now a miss");
  }
  return notApplicable(
      "no ray the model marks ambiguous at a shared edge or vertex hit on the device");
}

FaultResult doubleHitEdge(RecordFaultArgs& a) {
  for (const RayAmbiguity& amb : a.model.ambiguous) {
    const uint32_t k = sharedEdgeAnyHitRay(a, amb).triangles;
    if (!k) continue;
    const uint32_t before = a.dev.get(amb.ray, "any_hit_runs");
    a.dev.set(amb.ray, "any_hit_runs", before + (k - 1));
    const std::string counter = a.dev.bumpCounter(anyHitCounters(a.c), static_cast<int>(k - 1));
    return describeRay(amb.ray, "any-hit ran for all " + std::to_string(k) +
                                    " triangles sharing the " + ambiguityReasonName(amb.reason) +
                                    counterNote(counter, static_cast<int>(k - 1)));
  }
  return notApplicable("no ray through a shared edge or vertex whose candidates any-hit ignored");
}

FaultResult missAfterClosestHit(RecordFaultArgs& a) {
  RecordEdit& dev = a.dev;
  uint32_t ray;
  if (!findClear(
          a,
          [&](uint32_t r) {
            return dev.get(r, "closest_hit_runs") > 0 && dev.get(r, "miss_runs") == 0;
          },
          &ray))
    return notApplicable("no clear ray that ran closest-hit");
  dev.set(ray, "miss_runs", 1);
  const std::string counter = dev.bumpCounter(missCounters(a.c), +1);
  return describeRay(ray, "miss_runs 0 -> 1 after closest-hit" + counterNote(counter, +1));
}

Results perfectDevice(const Case& c, const Results& model) {
  Results device = model;
  if (device.records.empty()) return device;
  RecordEdit dev{device};
  const RecordView mod{model};
  const std::set<uint32_t> amb = ambiguousRays(model);
  RecordFaultArgs a{c, dev, mod, model, amb};
  for (const RayAmbiguity& r : model.ambiguous) {
    const uint32_t extra = sharedEdgeAnyHitRay(a, r).model_hits;
    if (extra < 2) continue;
    dev.set(r.ray, "any_hit_runs", dev.get(r.ray, "any_hit_runs") - (extra - 1));
    dev.bumpCounter(anyHitCounters(c), -static_cast<int>(extra - 1));
  }
  return device;
}

}  // namespace rayspec
