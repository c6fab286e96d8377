#include "compare/compare_results.h"

#include <set>

#include "compare/compare_parts.h"

namespace rayspec {

Verdict backendVerdict(const Results& r) {
  Verdict v;
  if (r.ok()) return v;
  Finding f;
  switch (r.status) {
    case RunStatus::Ok:
    case RunStatus::Crash: f.status = Status::Crash; break;
    case RunStatus::NotSupported: f.status = Status::NotSupported; break;
    case RunStatus::Timeout: f.status = Status::Timeout; break;
  }
  f.message = r.backend + ": " + r.statusText();
  v.add(f);
  return v;
}

Verdict compareResults(const Case& c, const Plan& plan, const Results& device, const Results& model) {
  Verdict v = backendVerdict(device);
  if (v.status != Status::Pass) return v;
  const Verdict model_verdict = backendVerdict(model);
  if (model_verdict.status != Status::Pass) {
    // The model could not run the case: nothing to compare against. Never a pass.
    Finding f = model_verdict.findings.front();
    f.status = Status::NotSupported;
    f.message = "no reference: " + f.message;
    v.add(f);
    return v;
  }
  if (!device.validation_messages.empty()) {
    Finding f;
    f.rule = "validation";
    f.message = std::to_string(device.validation_messages.size()) +
                " validation-layer error(s); first: " + device.validation_messages.front();
    v.add(f);
  }
  if (device.width != model.width || device.height != model.height || device.records.size() != model.records.size()) {
    Finding f;
    f.message = "launch size or record count differs between device and model";
    v.add(f);
    return v;
  }
  std::set<uint32_t> ambiguous;
  for (const RayAmbiguity& a : model.ambiguous) ambiguous.insert(a.ray);
  compareCounters(c, device, model, ambiguous.size(), v);
  compareRecords(c, plan, device, model, v);
  compareAnyHitRuns(c, device, model, v);
  compareImages(plan, device, model, ambiguous, v);
  compareEqualImages(plan, device, model, v);
  return v;
}

}  // namespace rayspec
