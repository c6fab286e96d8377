#include <algorithm>
#include <sstream>

#include "compare/shared_edge.h"
#include "fault/planted_fault.h"
#include "fault/record_edit.h"
#include "model/model_backend.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

std::string describe(uint32_t ray, const std::string& what) {
  std::ostringstream s;
  s << "ray " << ray << ": " << what;
  return s.str();
}

FaultResult none(const std::string& why) { return {false, why}; }

// A ray the model found clear, on which the model's run counts satisfy pred.
template <typename Pred>
bool findClear(const RecordEdit& dev, const std::set<uint32_t>& ambiguous, Pred pred, uint32_t* out) {
  for (uint32_t ray = 0; ray < dev.rays(); ++ray) {
    if (ambiguous.count(ray) || !pred(ray)) continue;
    *out = ray;
    return true;
  }
  return false;
}

FaultResult dropMiss(const Case& c, RecordEdit& dev, RecordEdit& mod, const std::set<uint32_t>& amb) {
  uint32_t ray;
  if (!findClear(dev, amb, [&](uint32_t r) { return dev.get(r, "miss_runs") >= 1 && mod.get(r, "miss_runs") >= 1; }, &ray))
    return none("no clear ray ran a miss shader");
  const uint32_t before = dev.get(ray, "miss_runs");
  dev.set(ray, "miss_runs", 0);
  const std::string counter = dev.bumpCounter(missCounters(c), -1);
  return {true, describe(ray, "miss_runs " + std::to_string(before) + " -> 0" +
                                  (counter.empty() ? "" : ", counter '" + counter + "' - 1"))};
}

FaultResult swapPrimitiveId(RecordEdit& dev, const std::set<uint32_t>& amb) {
  for (uint32_t a = 0; a < dev.rays(); ++a) {
    if (amb.count(a) || !dev.written(a, "primitive_id") || dev.get(a, "closest_hit_runs") == 0) continue;
    for (uint32_t b = a + 1; b < dev.rays(); ++b) {
      if (amb.count(b) || !dev.written(b, "primitive_id") || dev.get(b, "closest_hit_runs") == 0) continue;
      const uint32_t pa = dev.get(a, "primitive_id"), pb = dev.get(b, "primitive_id");
      if (pa == pb) continue;
      dev.set(a, "primitive_id", pb);
      dev.set(b, "primitive_id", pa);
      return {true, "rays " + std::to_string(a) + " and " + std::to_string(b) + ": primitive ids " +
                        std::to_string(pa) + " and " + std::to_string(pb) + " swapped"};
    }
  }
  return none("no two clear hit rays with a recorded primitive_id that differs");
}

FaultResult chitAfterIgnore(const Case& c, RecordEdit& dev, const std::set<uint32_t>& amb) {
  uint32_t ray;
  auto missed = [&](uint32_t r) { return dev.get(r, "closest_hit_runs") == 0 && dev.get(r, "miss_runs") >= 1; };
  // Prefer a ray whose candidates any-hit ignored; else any ray that missed.
  if (!findClear(dev, amb, [&](uint32_t r) { return missed(r) && dev.get(r, "any_hit_runs") > 0; }, &ray) &&
      !findClear(dev, amb, missed, &ray))
    return none("no clear ray that missed");
  dev.set(ray, "closest_hit_runs", dev.get(ray, "closest_hit_runs") + 1);
  const std::string counter = dev.bumpCounter(closestHitCounters(c), +1);
  return {true, describe(ray, "closest_hit_runs 0 -> 1 (any-hit ran " + std::to_string(dev.get(ray, "any_hit_runs")) +
                                  " times)" + (counter.empty() ? "" : ", counter '" + counter + "' + 1"))};
}

FaultResult shiftT(RecordEdit& dev, const std::set<uint32_t>& amb) {
  uint32_t ray;
  if (!findClear(dev, amb, [&](uint32_t r) { return dev.get(r, "closest_hit_runs") > 0 && dev.written(r, "hit_t"); }, &ray))
    return none("no clear hit ray with a recorded hit_t");
  const float t = dev.getFloat(ray, "hit_t");
  dev.setFloat(ray, "hit_t", t + 1e-3f);
  return {true, describe(ray, "hit_t " + std::to_string(t) + " -> " + std::to_string(t + 1e-3f))};
}

bool noDuplicateAnyHit(const Case& c) {
  bool any = false;
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries) any = any || (g.flags & kGeometryNoDuplicateAnyHit);
  return any;
}

FaultResult duplicateAnyHit(const Case& c, RecordEdit& dev, RecordEdit& mod, const std::set<uint32_t>& amb) {
  if (!noDuplicateAnyHit(c)) return none("no geometry has no_duplicate_any_hit");
  uint32_t ray;
  // Prefer a ray whose candidates were all ignored (the model then ran any-hit
  // once on every primitive the ray crosses).
  if (!findClear(dev, amb, [&](uint32_t r) {
        return dev.get(r, "any_hit_runs") > 0 && mod.get(r, "closest_hit_runs") == 0;
      }, &ray) &&
      !findClear(dev, amb, [&](uint32_t r) { return dev.get(r, "any_hit_runs") > 0; }, &ray))
    return none("no clear ray ran any-hit");
  const uint32_t before = dev.get(ray, "any_hit_runs");
  dev.set(ray, "any_hit_runs", before + 1);
  const std::string counter = dev.bumpCounter(anyHitCounters(c), +1);
  return {true, describe(ray, "any_hit_runs " + std::to_string(before) + " -> " + std::to_string(before + 1) +
                                  (counter.empty() ? "" : ", counter '" + counter + "' + 1"))};
}

FaultResult leakEdge(const Case& c, RecordEdit& dev, const Results& model) {
  for (const RayAmbiguity& a : model.ambiguous) {
    if (a.reason != AmbiguityReason::Edge && a.reason != AmbiguityReason::Vertex) continue;
    if (!crossesSharedEdge(c, a) || a.ray >= dev.rays() || dev.get(a.ray, "closest_hit_runs") == 0) continue;
    dev.set(a.ray, "closest_hit_runs", 0);
    dev.set(a.ray, "miss_runs", 1);
    if (dev.written(a.ray, "hit")) dev.set(a.ray, "hit", 0);
    const std::string chit = dev.bumpCounter(closestHitCounters(c), -1);
    const std::string miss = dev.bumpCounter(missCounters(c), +1);
    return {true, describe(a.ray, "on a shared " + std::string(ambiguityReasonName(a.reason)) + ", now a miss")};
  }
  return none("no ray the model marks ambiguous at a shared edge or vertex hit on the device");
}

// A device that judges an interval end the wrong way: the model run again
// with that deviation; every ray it answers differently takes its record,
// and the counters move by the difference.
FaultResult deviate(ModelDeviation deviation, const Case& c, const Plan& plan, Results& device, const Results& model,
                    const std::set<uint32_t>& amb) {
  ModelOptions o;
  o.deviation = deviation;
  const Results faulty = runOnModel(c, plan, o);
  if (!faulty.ok() || faulty.records.size() != model.records.size()) return none("the model's faulty run failed");
  RecordEdit dev{device};
  const size_t words = recordWords();
  std::ostringstream rays;
  uint32_t changed = 0, clear = 0;
  for (uint32_t ray = 0; ray < dev.rays(); ++ray) {
    if (std::equal(faulty.records.begin() + ray * words, faulty.records.begin() + (ray + 1) * words,
                   model.records.begin() + ray * words))
      continue;
    dev.copyRay(ray, faulty);
    rays << (changed++ ? ", " : "") << ray << (amb.count(ray) ? " (ambiguous)" : "");
    if (!amb.count(ray)) ++clear;
  }
  if (!changed) return none("no ray meets a candidate at exactly an end of its interval");
  for (const auto& [name, value] : faulty.counters) {
    auto m = model.counters.find(name);
    auto d = device.counters.find(name);
    if (m == model.counters.end() || d == device.counters.end()) continue;
    d->second = static_cast<uint64_t>(static_cast<int64_t>(d->second) + static_cast<int64_t>(value) -
                                      static_cast<int64_t>(m->second));
  }
  return {true, "rays " + rays.str() + " answered as with " +
                    (deviation == ModelDeviation::ClosedTriangleInterval ? "a closed triangle interval"
                                                                         : "an open AABB interval") +
                    " (" + std::to_string(clear) + " clear)"};
}

}  // namespace

FaultResult plantFault(const std::string& name, const Case& c, const Plan& plan, Results& device,
                       const Results& model) {
  if (device.records.empty() || device.records.size() != model.records.size())
    return none("no per-ray records to corrupt");
  RecordEdit dev{device};
  Results model_copy = model;
  RecordEdit mod{model_copy};
  const std::set<uint32_t> amb = ambiguousRays(model);
  if (name == "drop-miss") return dropMiss(c, dev, mod, amb);
  if (name == "swap-primitive-id") return swapPrimitiveId(dev, amb);
  if (name == "chit-after-ignore") return chitAfterIgnore(c, dev, amb);
  if (name == "shift-t") return shiftT(dev, amb);
  if (name == "duplicate-any-hit") return duplicateAnyHit(c, dev, mod, amb);
  if (name == "leak-edge") return leakEdge(c, dev, model);
  if (name == "closed-triangle-interval")
    return deviate(ModelDeviation::ClosedTriangleInterval, c, plan, device, model, amb);
  if (name == "open-aabb-interval") return deviate(ModelDeviation::OpenAabbInterval, c, plan, device, model, amb);
  return none(isProcessFault(name) ? "a process fault" : "unknown fault '" + name + "'");
}

}  // namespace rayspec
