#include "compare/compare_results.h"

#include <set>

#include "compare/any_hit_repeat_verdict.h"
#include "compare/compare_parts.h"
#include "compare/endless_restarts_verdict.h"
#include "compare/order_dependent_verdict.h"
#include "compare/undefined_behaviour.h"

namespace rayspec {

Verdict backendVerdict(const Results& r) {
  Verdict v;
  if (r.ok()) return v;
  Finding f;
  switch (r.status) {
    case SideStatus::Ok:
    case SideStatus::Crash:
      f.status = Status::Crash;
      break;
    case SideStatus::NotSupported:
      f.status = Status::NotSupported;
      break;
    case SideStatus::Timeout:
      f.status = Status::Timeout;
      break;
    case SideStatus::Refused:
      f.status = Status::Fail;
      f.rule = "driver";
      break;
    case SideStatus::InvalidShader:
      f.status = Status::CaseError;
      f.rule = "generated-shader";
      break;
  }
  f.message = r.backend + ": " + r.statusText();
  v.add(f);
  return v;
}

Verdict compareResults(const Case& c, const Plan& plan, const Results& device,
                       const Results& model) {
  Verdict v = backendVerdict(device);
  // R-UB first: it decides whether anything is judged at all.
  if (!judgeUndefinedBehaviour(c, device, model, v)) return v;
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
  for (const DeviceFinding& found : device.device_findings) {
    Finding f;
    f.rule = found.rule;
    f.message = found.message;
    v.add(f);
  }
  if (!c.expected_rejections.empty()) {  // no launch: the compiler's answers only
    compareRejections(c, device, model, v);
    return v;
  }
  if (device.width != model.width || device.height != model.height ||
      device.records.size() != model.records.size()) {
    Finding f;
    f.message = "launch size or record count differs between device and model";
    v.add(f);
    return v;
  }
  // R-AHIT-DUP: what any-hit repetition may change is diagnosed or left out.
  if (!judgeAnyHitRepeat(c, model, v)) return v;
  // R-ORDER-UNSPEC: answers that depend on more orders than the model tries.
  if (!judgeOrderDependence(model, v)) return v;
  // R-RQ-INIT: a query restarted past the bound (endless restarts).
  if (!judgeEndlessRestarts(model, v)) return v;
  // Rays left out of every per-ray comparison: the ambiguous ones are checked
  // against their legal answers instead; the undefined ones (R-UB) not at all.
  std::set<uint32_t> ambiguous, undefined;
  for (const RayAmbiguity& a : model.ambiguous) ambiguous.insert(a.ray);
  for (const UndefinedRay& u : model.undefined) undefined.insert(u.ray);
  std::set<uint32_t> masked = ambiguous;
  masked.insert(undefined.begin(), undefined.end());
  compareCounters(c, plan, device, model, undefined.size(), v);
  compareRecords(c, plan, device, model, undefined, v);
  compareAnyHitRuns(c, device, model, undefined, v);
  compareImages(plan, device, model, masked, v);
  compareImagesToRecords(device, ambiguous, v);
  compareEqualImages(plan, device, model, v);
  return v;
}

}  // namespace rayspec
