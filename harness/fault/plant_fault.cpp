#include "fault/fault_impl.h"
#include "plan/plan.h"

namespace rayspec {
namespace {

const FaultImpl* findImpl(const std::string& name) {
  for (const FaultImpl& f : faultImpls())
    if (name == f.name) return &f;
  return nullptr;
}

// A fault a device shows only in another order than near to far (a legal
// one, ModelFaults::order) that answers here as that order alone does: what
// changed is the order, not the rule the fault breaks.
bool onlyTheOrder(const FaultImpl& f, const Case& c, const ModelOptions& options,
                  const Results& faulty) {
  if (options.faults.order == CandidateOrder::Distance ||
      std::string(f.breaks).rfind("legal:", 0) == 0)
    return false;
  ModelOptions legal;
  legal.faults.order = options.faults.order;
  legal.faults.order_seed = options.faults.order_seed;
  const Results ordered = perfectDevice(c, runOnModel(c, derivePlan(c), legal));
  return ordered.ok() && sameOutput(ordered, faulty);
}

// The model's exact tier on the case as the breaking device sees it.
FaultResult runMutated(const FaultImpl& f, const Case& c, Results& device) {
  Case mutated = c;
  ModelOptions options;
  const std::string what = f.mutate(mutated, options);
  if (what.empty()) return notApplicable("nothing in the case for this fault to change");
  // A device that answers its own ambiguous rays one legal way.
  const Results r = perfectDevice(mutated, runOnModel(mutated, derivePlan(mutated), options));
  if (!r.ok())
    return notApplicable("the mutated case does not run on the model: " + r.statusText());
  if (onlyTheOrder(f, c, options, r))
    return notApplicable("changes nothing a device deciding in its order does not: " + what);
  device.counters = r.counters;
  device.records = r.records;
  device.images = r.images;
  return {true, what};
}

}  // namespace

FaultResult plantFault(const std::string& name, const Case& c, const Plan& plan, Results& device,
                       const Results& model) {
  const FaultImpl* f = findImpl(name);
  if (!f) return notApplicable("unknown fault '" + name + "'");
  if (f->kind == FaultKind::Process) return notApplicable("a process fault");
  if (f->kind == FaultKind::Vulkan)
    return notApplicable("made on a live device (rayspec run --plant-fault " + name + ")");
  // A zero-sized launch has no records, and its counters may still be wrong.
  // Nor does a case whose shaders are only compiled (expect_rejected), nor
  // one that keeps only counters (plan.records off).
  const bool no_records = c.rays.rays.empty() || !c.expected_rejections.empty() || !plan.records;
  if (device.records.size() != model.records.size() || (device.records.empty() && !no_records))
    return notApplicable("no per-ray records to corrupt");
  if (f->kind == FaultKind::CaseMutation) return runMutated(*f, c, device);
  RecordEdit dev{device};
  const RecordView mod{model};
  const std::set<uint32_t> amb = ambiguousRays(model);
  RecordFaultArgs args{c, dev, mod, model, amb};
  return f->record(args);
}

}  // namespace rayspec
