// Devices the specification allows that answer ambiguous rays otherwise than
// the model (rayspec mutate's legal devices, mutate/legal_devices.h).
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

}  // namespace

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

}  // namespace rayspec
