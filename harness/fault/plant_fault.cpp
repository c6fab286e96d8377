#include "fault/fault_impl.h"
#include "plan/plan.h"

namespace rayspec {
namespace {

const FaultImpl* findImpl(const std::string& name) {
  for (const FaultImpl& f : faultImpls())
    if (name == f.name) return &f;
  return nullptr;
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
