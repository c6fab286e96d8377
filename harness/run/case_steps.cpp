#include "run/case_steps.h"

#include <filesystem>

#include "base/visible_text.h"
#include "bundle/results_io.h"
#include "compare/compare_results.h"
#include "plan/plan.h"
#include "report/baseline_gate.h"
#include "report/case_cost.h"
#include "report/case_journal.h"
#include "results/file_name.h"
#include "run/device_results.h"
#include "run/fault_seam.h"
#include "run/judge_case.h"
#include "run/model_adapter.h"
#include "run/vulkan_adapter.h"
#include "vulkan/case_support.h"

namespace rayspec {
namespace {

Side modelSide(const RunOptions& opt) {
  ModelOptions mopt;
  mopt.tier = checkedModelTier(opt);
  mopt.threads = opt.threads;
  Side s{"model", "model", [mopt] { return std::make_unique<ModelAdapter>(mopt); }, {}};
  return s;
}

Side deviceSide(const RunOptions& opt, std::shared_ptr<const Results> model,
                const std::string& fault) {
  const VulkanOptions vopt = vulkanOptions(opt);
  Side s{"device", "vulkan", [vopt] { return std::make_unique<VulkanAdapter>(vopt); }, {}};
  // A device run saved elsewhere, read back (run/device_results.h).
  if (!opt.device_results.empty())
    s.make = [dir = opt.device_results] {
      return std::make_unique<SavedDevice>(dir);
    };
  armDeviceSide(s, fault, std::move(model), opt.out);  // test only: run/fault_seam.h
  return s;
}

// An outcome without a comparison: `v` holds why.
CaseOutcome unjudged(const Case& c, const Plan& plan, const Results& device, const Results& model,
                     Verdict v) {
  CaseOutcome out;
  out.name = c.name;
  out.rules = c.rules;
  out.device_seconds = device.seconds;
  out.model_seconds = model.seconds;
  for (const ImageOutput& im : plan.images) out.images.push_back(im.name);
  out.verdict = std::move(v);
  return out;
}

// One side only ran: its own status, validation errors included; never more
// than that. Nothing was compared, so the case did not pass: it was not judged.
CaseOutcome oneSideOutcome(const Case& c, const Plan& plan, const Results& device,
                           const Results& model, bool device_ran) {
  const Results& only = device_ran ? device : model;
  Verdict v = backendVerdict(only);
  for (const std::string& m : only.validation_messages)
    v.add({Status::Fail, "validation", m, {}, 0});
  v.add(
      {Status::NotSupported,
       "no-reference",
       std::string("only the ") + (device_ran ? "device" : "model") + " ran: nothing was compared",
       {},
       0});
  return unjudged(c, plan, device, model, v);
}

// The per-ray records as text (records.csv beside each side's bundle), for
// people looking into the case.
Result<void> writeRecordsCsvFiles(const std::string& dir, const Results& device,
                                  const Results& model, const Plan& plan) {
  for (const auto& [side, r] : {std::pair{"/device", &device}, std::pair{"/model", &model}})
    if (std::filesystem::is_directory(dir + side))
      if (const Result<void> written =
              writeRecordsCsv(*r, dir + side + "/records.csv", plan.record_fields);
          !written)
        return errorOf(ErrorKind::Harness, written.error().format());
  return {};
}

bool ended(const Results& r) {
  return r.status == SideStatus::Crash || r.status == SideStatus::Timeout;
}

// The model crashed or hung: nothing to judge the device by (it did not run).
CaseOutcome noReferenceOutcome(const Case& c, const Plan& plan, const Results& model) {
  Verdict v = backendVerdict(model);
  v.add({Status::NotSupported,
         "no-reference",
         "the device side did not run: the model gave no reference",
         {},
         0});
  return unjudged(c, plan, Results{}, model, v);
}

}  // namespace

CaseOutcome judgeSides(const Case& c, const Plan& plan, const Results* device, const Results* model,
                       const std::string& dir) {
  CaseOutcome out;
  if (model && ended(*model)) {
    out = noReferenceOutcome(c, plan, *model);
  } else if (device && !model && device->status == SideStatus::NotSupported &&
             device->validation_messages.empty()) {
    // The device cannot run the case (decided before the model ran, or in a
    // run without it): its NotSupported, as judgeCase gives it with a model.
    out = unjudged(c, plan, *device, Results{}, backendVerdict(*device));
    out.device_name = device->device;
  } else if (device && model) {
    out = judgeCase(c, plan, *device, *model, dir);
    out.device_name = device->device;
  } else if (device || model) {
    out = oneSideOutcome(c, plan, device ? *device : Results{}, model ? *model : Results{},
                         device != nullptr);
    if (device) out.device_name = device->device;
  } else {
    Verdict v;
    v.add({Status::NotSupported, "no-reference", "neither side ran", {}, 0});
    out = unjudged(c, plan, Results{}, Results{}, v);
  }
  out.deriveFromVerdict();
  return out;
}

SideFor modelSideFor(const RunOptions& opt) {
  return [opt](const Case&, const std::string&) -> Result<Side> {
    return modelSide(opt);
  };
}

SideFor deviceSideFor(const RunOptions& opt) {
  return [opt](const Case& c, const std::string& dir) -> Result<Side> {
    const std::string fault = plantedFaultIn(opt, c.name);
    auto model = std::make_shared<Results>();
    if (faultReadsModel(fault) && !opt.no_model) {
      // The model's answer, which a planted fault chooses its rays by, is the
      // bundle the model side of this case just wrote.
      Result<Results> read =
          readResults(std::filesystem::path(dir).parent_path().string() + "/model");
      if (!read)
        return errorOf(ErrorKind::Harness,
                       "device side: the model's results: " + read.error().format());
      *model = std::move(*read);
    }
    return deviceSide(opt, model, fault);
  };
}

CaseOutcome caseErrorOutcome(const std::string& name, const std::vector<std::string>& rules,
                             const std::string& rule, const std::string& message) {
  CaseOutcome out;
  out.name = name;
  out.rules = rules;
  out.verdict.add({Status::CaseError, rule, message, {}, 0});
  out.deriveFromVerdict();
  return out;
}

std::optional<CaseOutcome> caseFileError(const CaseFile& file, const ParseResult& parsed) {
  std::string message;
  for (const Error& e : parsed.errors) message += (message.empty() ? "" : "\n  ") + e.format();
  if (parsed.value && message.empty()) return std::nullopt;
  if (message.empty()) message = visibleText(file.path) + ": cannot read the case file";
  return caseErrorOutcome(file.name,
                          parsed.value ? parsed.value->rules : std::vector<std::string>{},
                          "case-file", message);
}

CaseOutcome guardCase(const std::string& name, const std::vector<std::string>& rules,
                      const std::function<Result<CaseOutcome>()>& step) {
  try {
    Result<CaseOutcome> out = step();
    if (out) return std::move(*out);
    return caseErrorOutcome(name, rules, "harness",
                            "the harness failed on this case: " + out.error().format());
  } catch (const std::exception& e) {  // the standard library's, or the model tier's name
    return caseErrorOutcome(name, rules, "harness",
                            std::string("the harness failed on this case: ") + e.what());
  }
}

CaseRunner::CaseRunner(const RunOptions& options, Backend* device, Backend* model,
                       std::optional<ProbedDevice> probed)
    : opt_(options), device_(device), model_(model), probed_(std::move(probed)) {
  if (!opt_.device_results.empty() && opt_.no_isolation) {
    saved_device_ = std::make_unique<SavedDevice>(opt_.device_results);
    device_ = saved_device_.get();
  }
}

Result<std::optional<Results>> CaseRunner::refusedHere(const Case& c, const Plan& plan,
                                                       const std::string& dir) const {
  if (!probed_ || !plantedFaultIn(opt_, c.name).empty()) return std::optional<Results>();
  const Result<void> runs = checkCaseRuns(probed_->info, probed_->validation_layer, c, plan);
  if (runs || runs.error().kind != ErrorKind::NotSupported) return std::optional<Results>();
  Results r;  // as VulkanEngine::run gives it
  r.backend = "vulkan";
  r.device = probed_->info.name;
  r.case_name = c.name;
  r.case_file = c.file;
  r.case_hash = c.source_hash;
  r.width = c.rays.width;
  r.height = c.rays.height;
  r.setStatus(SideStatus::NotSupported, runs.error().format());
  if (const Result<void> written =
          writeResults(r, dir, plan.record_fields, BundleFiles{false, false});
      !written)
    return errorOf(ErrorKind::Harness, "device side: " + written.error().format());
  return std::optional<Results>(std::move(r));
}

Result<SideResult> CaseRunner::runSide(const std::function<Side()>& side, Backend* in_process,
                                       SideWorker* worker, const CaseSlot* slot, const Case& c,
                                       const Plan& plan, const std::string& dir) const {
  if (in_process) return runInProcess(side(), *in_process, c, plan, dir);
  if (worker) return worker->run(slot->index, plan, dir);
  return runIsolated(side(), c, plan, ChildLimits{opt_.timeout, opt_.memory_limit}, dir);
}

Result<CaseOutcome> CaseRunner::run(const Case& c, bool* interrupted, const std::string& subfolder,
                                    const CaseSlot* slot) const {
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
  if (want_device) {
    RAYSPEC_TRY(const std::optional<Results> refused, refusedHere(c, plan, dir + "/device"));
    if (refused) return costed(judgeSides(c, plan, &*refused, nullptr, dir), *refused, model);
  }
  if (want_model) {
    RAYSPEC_TRY(SideResult m, runSide([&] { return modelSide(opt_); }, model_,
                                      slot ? slot->model : nullptr, slot, c, plan, dir + "/model"));
    if ((*interrupted = m.interrupted)) return CaseOutcome{};
    model = std::move(m.results);
    // The model crashed or hung: the device side does not run.
    if (ended(model)) return costed(judgeSides(c, plan, nullptr, &model, dir), device, model);
  }
  std::string fault_note;
  if (want_device) {
    const auto side = [&] {
      return deviceSide(opt_, std::make_shared<Results>(model), plantedFaultIn(opt_, c.name));
    };
    RAYSPEC_TRY(SideResult d, runSide(side, device_, slot ? slot->device : nullptr, slot, c, plan,
                                      dir + "/device"));
    if ((*interrupted = d.interrupted)) return CaseOutcome{};
    device = std::move(d.results);
    fault_note = d.note;
  }
  StepTimer judge_time(parent, CostStep::Comparison);
  CaseOutcome out =
      judgeSides(c, plan, want_device ? &device : nullptr, want_model ? &model : nullptr, dir);
  judge_time.stop();
  if (!fault_note.empty()) out.verdict.add({Status::Pass, "planted-fault", fault_note, {}, 0});
  out.deriveFromVerdict();
  if (out.status != Status::Pass || opt_.records_csv) {
    StepTimer csv_time(parent, CostStep::RecordsCsv);
    RAYSPEC_TRY_VOID(writeRecordsCsvFiles(dir, device, model, plan));
  }
  return costed(std::move(out), device, model);
}

namespace {

// The CaseError a case becomes when the reports cannot show its details.
CaseOutcome unshownCase(const CaseOutcome& o, const Baseline& baseline, const Error& why) {
  CaseOutcome out = caseErrorOutcome(o.name, o.rules, "harness",
                                     "the reports could not show this case: " + why.format());
  applyBaseline(baseline, out);
  return out;
}

}  // namespace

void journalCase(CaseOutcome& outcome, const Baseline& baseline, const std::string& dir) {
  StepTimer report_time(outcome.cost[CostSide::Parent], CostStep::Reports);
  Result<void> written = appendJournal(outcome, dir);
  if (!written && written.error().kind == ErrorKind::Input) {
    // This case's details do not go into the reports: keep the case, as a CaseError, without them.
    outcome = unshownCase(outcome, baseline, written.error());
    written = appendJournal(outcome, dir);
  }
  report_time.stop();
  // Where the case's time went, beside its bundles (a skipped case has none;
  // a name that is no case name never became a folder of this run).
  if (caseNameProblem(outcome.name).empty() &&
      std::filesystem::is_directory(dir + "/" + outcome.name))
    if (const Result<void> cost = writeCaseCost(outcome, dir + "/" + outcome.name + "/cost.json");
        !cost && written)
      written = cost;
  if (!written) std::fprintf(stderr, "%s\n", visibleLine(written.error().format()).c_str());
}

Result<void> writeRunReports(std::vector<CaseOutcome>& outcomes, const Baseline& baseline,
                             const RunInfo& info, const std::string& dir,
                             const ReportWriter& write) {
  const Result<void> written = write(outcomes, info, dir);
  // Only a case's details are worth looking for case by case; a file that
  // cannot be written fails alike for every case.
  if (written || written.error().kind != ErrorKind::Input) return written;
  // Some case's details broke the reports: each case alone, into a scratch
  // folder, finds which; those become CaseErrors and the reports are written again.
  const std::string scratch = dir + "/.report-check";
  for (CaseOutcome& o : outcomes)
    if (const Result<void> alone = write({o}, info, scratch);
        !alone && alone.error().kind == ErrorKind::Input)
      o = unshownCase(o, baseline, alone.error());
  std::error_code ec;
  std::filesystem::remove_all(scratch, ec);
  const Result<void> again = write(outcomes, info, dir);
  if (!again && again.error().kind == ErrorKind::Input)
    return errorOf(ErrorKind::Harness, "cannot write the reports: " + again.error().format());
  return again;
}

}  // namespace rayspec
