#include "run/case_steps.h"

#include <fnmatch.h>

#include <filesystem>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "plan/plan.h"
#include "report/baseline_gate.h"
#include "report/case_cost.h"
#include "results/file_name.h"
#include "results/results_io.h"
#include "run/device_results.h"
#include "run/judge_case.h"
#include "run/model_adapter.h"
#include "run/vulkan_adapter.h"
#include "vulkan/device_errors.h"

namespace rayspec {
namespace {

Side modelSide(const RunOptions& opt) {
  ModelOptions mopt;
  mopt.tier = parseModelTier(opt.model_tier);
  mopt.threads = opt.threads;
  Side s{"model", "model", [mopt] { return std::make_unique<ModelAdapter>(mopt); }, {}};
  return s;
}

Side deviceSide(const RunOptions& opt, const Results& model, const std::string& fault) {
  VulkanOptions vopt;
  vopt.device_filter = opt.device;
  vopt.validation = !opt.no_validation;
  Side s{"device", "vulkan", [vopt] { return std::make_unique<VulkanAdapter>(vopt); }, {}};
  if (!opt.device_results.empty())  // a device run saved elsewhere, read back (run/device_results.h)
    s.make = [dir = opt.device_results] { return std::make_unique<SavedDevice>(dir); };
  if (const std::optional<InjectedVkError> injected = deviceErrorFault(fault)) {
    // A Vulkan call fails on purpose for this case only.
    s.before = [e = *injected] { injectVkError(e); };
    s.after = [fault, e = *injected](const Case&, const Plan&, Results&) -> std::string {
      injectVkError({});
      return "planted fault " + fault + ": " + e.call + " returns " + vkResultName(e.result);
    };
    return s;
  }
  if (!fault.empty())
    s.after = [fault, &model, out = opt.out](const Case& c, const Plan& plan, Results& device) -> std::string {
      raiseProcessFault(fault, c.name, out);  // crash, hang: only in a child (run loop refuses them in process)
      if (isProcessFault(fault)) return {};
      const FaultResult f = plantFault(fault, c, plan, device, model);
      return (f.applied ? "planted fault " : "planted fault not applicable: ") + fault + ": " + f.what;
    };
  return s;
}

// An outcome without a comparison: `v` holds why.
CaseOutcome unjudged(const Case& c, const Plan& plan, const Results& device, const Results& model, Verdict v) {
  CaseOutcome out;
  out.name = c.name;
  out.rules = c.rules;
  out.device_seconds = device.seconds;
  out.model_seconds = model.seconds;
  for (const ImageOutput& im : plan.images) out.images.push_back(im.name);
  out.verdict = std::move(v);
  return out;
}

bool ended(const Results& r) { return r.status == RunStatus::Crash || r.status == RunStatus::Timeout; }

}  // namespace

CaseOutcome caseErrorOutcome(const std::string& name, const std::vector<std::string>& rules, const std::string& rule,
                             const std::string& message) {
  CaseOutcome out;
  out.name = name;
  out.rules = rules;
  out.verdict.add({Status::CaseError, rule, message, {}, 0});
  out.status = out.verdict.status;
  out.headline = out.verdict.headline();
  return out;
}

std::optional<CaseOutcome> caseFileError(const CaseFile& file, const ParseResult& parsed) {
  std::string message;
  for (const CaseError& e : parsed.errors) message += (message.empty() ? "" : "\n  ") + e.format();
  if (parsed.value && message.empty()) return std::nullopt;
  if (message.empty()) message = file.path + ": cannot read the case file";
  return caseErrorOutcome(file.name, parsed.value ? parsed.value->rules : std::vector<std::string>{}, "case-file",
                          message);
}

CaseOutcome guardCase(const std::string& name, const std::vector<std::string>& rules,
                      const std::function<CaseOutcome()>& step) {
  try {
    return step();
  } catch (const std::exception& e) {
    return caseErrorOutcome(name, rules, "harness", std::string("the harness failed on this case: ") + e.what());
  }
}

CaseRunner::CaseRunner(const RunOptions& options, Backend* device, Backend* model)
    : opt_(options), device_(device), model_(model) {
  if (!opt_.device_results.empty() && opt_.no_isolation) {
    saved_device_ = std::make_unique<SavedDevice>(opt_.device_results);
    device_ = saved_device_.get();
  }
}

SideResult CaseRunner::runSide(const Side& side, Backend* in_process, const Case& c, const Plan& plan,
                               const std::string& dir) const {
  if (in_process) return runInProcess(side, *in_process, c, plan, dir);
  return runIsolated(side, c, plan, ChildLimits{opt_.timeout, opt_.memory_limit}, dir);
}

CaseOutcome CaseRunner::run(const Case& c, bool* interrupted, const std::string& subfolder) const {
  *interrupted = false;
  StepCosts parent;
  StepTimer plan_time(parent, CostStep::Plan);
  const Plan plan = derivePlan(c);
  plan_time.stop();
  // The outcome with what each side and this process spent on the case.
  const auto costed = [&parent](CaseOutcome out, const Results& device, const Results& model) {
    out.cost[CostSide::Parent] += parent;
    out.cost[CostSide::Model] += model.cost;
    out.cost[CostSide::Device] += device.cost;
    return out;
  };
  const std::string dir = opt_.out + "/" + c.name + subfolder;
  removeCaseOutputs(dir);  // no stale bundle from an earlier run
  Results device, model;
  const bool want_device = !opt_.no_device, want_model = !opt_.no_model;
  if (want_model) {
    SideResult m = runSide(modelSide(opt_), model_, c, plan, dir + "/model");
    if ((*interrupted = m.interrupted)) return {};
    model = std::move(m.results);
    if (ended(model)) {
      // The model crashed or hung: nothing to judge the device by.
      Verdict v = backendVerdict(model);
      v.add({Status::NotSupported, "no-reference", "the device side did not run: the model gave no reference", {}, 0});
      CaseOutcome out = unjudged(c, plan, device, model, v);
      out.status = out.verdict.status;
      out.headline = out.verdict.headline();
      return costed(std::move(out), device, model);
    }
  }
  std::string fault_note;
  const std::string fault =
      fnmatch(opt_.plant_fault_in.c_str(), c.name.c_str(), 0) == 0 ? opt_.plant_fault : std::string();
  if (want_device) {
    SideResult d = runSide(deviceSide(opt_, model, fault), device_, c, plan, dir + "/device");
    if ((*interrupted = d.interrupted)) return {};
    device = std::move(d.results);
    fault_note = d.note;
  }
  CaseOutcome out;
  if (want_device && want_model) {
    StepTimer judge_time(parent, CostStep::Comparison);
    out = judgeCase(c, plan, device, model, dir);
  } else {
    // One side only: its own status, validation errors included; never more than that.
    const Results& only = want_device ? device : model;
    Verdict v = backendVerdict(only);
    for (const std::string& m : only.validation_messages) v.add({Status::Fail, "validation", m, {}, 0});
    // Nothing was compared, so the case did not pass: it was not judged.
    v.add({Status::NotSupported, "no-reference",
           std::string("only the ") + (want_device ? "device" : "model") + " ran: nothing was compared", {}, 0});
    out = unjudged(c, plan, device, model, v);
  }
  if (!fault_note.empty()) out.verdict.add({Status::Pass, "planted-fault", fault_note, {}, 0});
  out.status = out.verdict.status;
  out.headline = out.verdict.headline();
  out.device_name = device.device;
  if (out.status != Status::Pass || opt_.records_csv) {
    // The per-ray records as text, for people looking into the case.
    StepTimer csv_time(parent, CostStep::RecordsCsv);
    for (const auto& [side, r] : {std::pair{"/device", &device}, std::pair{"/model", &model}})
      if (std::filesystem::is_directory(dir + side))
        if (const std::string e = writeRecordsCsv(*r, dir + side + "/records.csv", plan.record_fields); !e.empty())
          throw HarnessError(e);
  }
  return costed(std::move(out), device, model);
}

void reportCase(CaseOutcome outcome, const Baseline& baseline, const RunInfo& info, const std::string& dir,
                RunSummary& summary, const ReportWriter& write) {
  std::vector<CaseOutcome> all = summary.outcomes();
  all.push_back(outcome);
  std::string err;
  StepTimer report_time(outcome.cost[CostSide::Parent], CostStep::Reports);
  try {
    err = write(all, info, dir);
  } catch (const std::exception& e) {
    // This case's details broke the reports: keep the case, as a CaseError, without them.
    outcome = caseErrorOutcome(outcome.name, outcome.rules, "harness",
                               std::string("the reports could not show this case: ") + e.what());
    applyBaseline(baseline, outcome);
    all.back() = outcome;
    try {
      err = write(all, info, dir);
    } catch (const std::exception& again) {
      err = std::string("cannot write the reports: ") + again.what();
    }
  }
  report_time.stop();
  // Where the case's time went, beside its bundles (a skipped case has none;
  // a name that is no case name never became a folder of this run).
  if (caseNameProblem(outcome.name).empty() && std::filesystem::is_directory(dir + "/" + outcome.name))
    if (const std::string e = writeCaseCost(outcome, dir + "/" + outcome.name + "/cost.json"); !e.empty() && err.empty())
      err = e;
  summary.add(outcome);
  if (!err.empty()) std::fprintf(stderr, "%s\n", err.c_str());
}

}  // namespace rayspec
