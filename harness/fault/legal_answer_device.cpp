// Devices the specification allows that answer ambiguous rays otherwise than
// the model (rayspec mutate's legal devices, mutate/legal_devices.h).
#include <array>
#include <optional>
#include <set>

#include "fault/planted_fault.h"
#include "model/model_engine.h"

namespace rayspec {
namespace {

Results modelAs(const Case& c, const Plan& plan, const ModelFaults& faults, unsigned threads) {
  ModelOptions o;
  o.threads = threads;
  o.faults = faults;
  return perfectDevice(c, runOnModel(c, plan, o));
}

// Every key (instance, geometry, primitive) a candidate of the scene may
// have: an instance counted both among all instances and within its own top
// level (whichever the traversal names it by); nullopt past `most`.
std::optional<std::vector<std::array<uint32_t, 3>>> candidateKeys(const Scene& scene, size_t most) {
  std::set<std::array<uint32_t, 3>> keys;
  std::vector<uint32_t> in_level(scene.tlasCount(), 0);
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& inst = scene.instances[i];
    const uint32_t own = in_level[inst.tlas]++;
    if (!inst.blas || *inst.blas >= scene.blases.size()) continue;
    const Blas& b = scene.blases[*inst.blas];
    for (uint32_t g = 0; g < b.geometries.size(); ++g)
      for (uint32_t p = 0; p < b.geometries[g].primitiveCount(); ++p) {
        keys.insert({i, g, p});
        keys.insert({own, g, p});
        if (keys.size() > most) return std::nullopt;
      }
  }
  return std::vector<std::array<uint32_t, 3>>(keys.begin(), keys.end());
}

}  // namespace

bool oneCandidateAtMost(const Scene& scene) {
  return candidateKeys(scene, 1).has_value();
}

std::vector<NamedDevice> lastCandidateDevices(const Case& c, const Plan& plan, unsigned threads) {
  std::vector<NamedDevice> out;
  const auto keys = candidateKeys(c.scene, kMaxLastCandidates);
  if (!keys || keys->size() < 2) return out;  // one candidate is never decided after another
  for (const auto& [instance, geometry, primitive] : *keys) {
    ModelFaults f;
    f.order = CandidateOrder::OneLast;
    f.last_instance = instance;
    f.last_geometry = geometry;
    f.last_primitive = primitive;
    out.push_back({"last-" + std::to_string(instance) + "." + std::to_string(geometry) + "." +
                       std::to_string(primitive),
                   modelAs(c, plan, f, threads)});
  }
  return out;
}

Results legalAnswerDevice(const Case& c, const Plan& plan, uint32_t answer, unsigned threads) {
  ModelFaults f;
  f.legal_answer = answer;
  return modelAs(c, plan, f, threads);
}

Results passBetweenEdgesDevice(const Case& c, const Plan& plan, unsigned threads) {
  ModelFaults f;
  f.pass_between_edges = true;
  return modelAs(c, plan, f, threads);
}

Results aabbNeighboursDevice(const Case& c, const Plan& plan, unsigned threads) {
  ModelFaults f;
  f.aabb_neighbours_run = true;
  return modelAs(c, plan, f, threads);
}

Results aabbNearDevice(const Case& c, const Plan& plan, unsigned threads) {
  ModelFaults f;
  f.aabb_near_offered = true;
  return modelAs(c, plan, f, threads);
}

}  // namespace rayspec
