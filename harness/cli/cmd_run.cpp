#include <fnmatch.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <set>

#include "case/parse_case.h"
#include "cli/case_discovery.h"
#include "cli/commands.h"
#include "cli/device_child.h"
#include "cli/judge_case.h"
#include "fault/planted_fault.h"
#include "metamorphic/permute_case.h"
#include "compare/compare_results.h"
#include "model/model_backend.h"
#include "plan/plan.h"
#include "report/baseline.h"
#include "report/rule_catalog.h"
#include "report/run_summary.h"
#include "report/write_reports.h"
#include "results/results_io.h"
#include "vulkan/vulkan_backend.h"

namespace rayspec {
namespace {

constexpr int kExitNotSupported = 77;  // ctest's SKIP_RETURN_CODE for a single case

bool validationLayerInstalled() {
  if (const char* path = std::getenv("VK_LAYER_PATH"))
    if (std::filesystem::exists(std::string(path) + "/VkLayer_khronos_validation.json")) return true;
  for (const char* dir : {"/usr/share/vulkan/explicit_layer.d", "/usr/local/share/vulkan/explicit_layer.d",
                          "/etc/vulkan/explicit_layer.d"})
    if (std::filesystem::exists(std::string(dir) + "/VkLayer_khronos_validation.json")) return true;
  return false;
}

std::string now() {
  char text[64];
  const std::time_t t = std::time(nullptr);
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&t));
  return text;
}

// Rule labels a case names that the catalog lacks are case errors.
std::string unknownRules(const Case& c, const std::vector<Rule>& catalog) {
  std::string unknown;
  for (const std::string& label : c.rules) {
    bool known = false;
    for (const Rule& r : catalog) known = known || r.label == label;
    if (!known) unknown += (unknown.empty() ? "" : ", ") + label;
  }
  return unknown;
}

// Runs one parsed case on the selected backends and compares. The model runs
// first (a planted fault chooses its rays by the model's answer), each bundle
// is written as soon as it exists.
CaseOutcome runOne(const Case& c, const RunOptions& opt, VulkanBackend* backend, const std::string& backend_error) {
  const Plan plan = derivePlan(c);
  const std::string dir = opt.out + "/" + c.name;
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);  // no stale bundle from an earlier run
  Results device, model;
  const bool want_device = !opt.no_device, want_model = !opt.no_model;
  if (want_model) {
    ModelOptions mopt;
    mopt.tier = parseModelTier(opt.model_tier);
    mopt.threads = opt.threads;
    model = runOnModel(c, plan, mopt);
    model.case_name = c.name;
    model.case_file = c.file;
    const std::string err = writeResults(model, dir + "/model", plan.record_fields);
    if (!err.empty()) std::fprintf(stderr, "%s\n", err.c_str());
  }
  std::string fault_note;
  const std::string fault =
      fnmatch(opt.plant_fault_in.c_str(), c.name.c_str(), 0) == 0 ? opt.plant_fault : std::string();
  if (want_device) {
    if (opt.no_isolation) {
      device = runDeviceInProcess(c, plan, model, backend, backend_error, fault, dir + "/device",
                                  &fault_note);
    } else {
      DeviceRun run;
      run.vulkan.device_filter = opt.device;
      run.vulkan.validation = !opt.no_validation;
      run.timeout_seconds = opt.timeout;
      run.fault = fault;
      device = runDeviceIsolated(c, plan, model, run, dir + "/device", &fault_note);
    }
  }
  CaseOutcome out;
  if (want_device && want_model) {
    out = judgeCase(c, plan, device, model, dir);
  } else {
    // One side only: its own status, validation errors included; never more than that.
    const Results& only = want_device ? device : model;
    Verdict v = backendVerdict(only);
    for (const std::string& m : only.validation_messages) v.add({Status::Fail, "validation", m, {}, 0});
    // Nothing was compared, so the case did not pass: it was not judged.
    v.add({Status::NotSupported, "no-reference",
           std::string("only the ") + (want_device ? "device" : "model") + " ran: nothing was compared", {}, 0});
    out.name = c.name;
    out.rules = c.rules;
    out.device_seconds = device.seconds;
    out.model_seconds = model.seconds;
    for (const ImageOutput& im : plan.images) out.images.push_back(im.name);
    out.verdict = v;
  }
  if (!fault_note.empty()) out.verdict.add({Status::Pass, "planted-fault", fault_note, {}, 0});
  out.status = out.verdict.status;
  out.headline = out.verdict.headline();
  out.device_name = device.device;
  return out;
}

}  // namespace

int runCases(const RunOptions& opt) {
  std::vector<CaseFile> files;
  if (!opt.case_files.empty()) {
    for (const std::string& f : opt.case_files) files.push_back(caseFileFor(f, opt.cases_dir));
  } else {
    files = findCases(opt.cases_dir, opt.filter);
  }
  if (files.empty()) {
    std::fprintf(stderr, "rayspec run: no case matches '%s' in %s\n", opt.filter.c_str(), opt.cases_dir.c_str());
    return 2;
  }
  const bool validation = !opt.no_validation;
  if (validation && opt.strict_validation && !validationLayerInstalled()) {
    std::fprintf(stderr, "rayspec run: the Khronos validation layer is not installed (vulkan-validationlayers); "
                         "run tools/setup.sh\n");
    return 2;
  }
  RunInfo info;
  info.started = now();
  info.model_tier = opt.no_model ? "none" : opt.model_tier;
  std::string catalog_error;
  info.catalog = loadRuleCatalog(opt.rules_file, &catalog_error);
  if (!catalog_error.empty()) std::fprintf(stderr, "rayspec run: %s\n", catalog_error.c_str());

  if (!opt.plant_fault.empty() && !isFaultName(opt.plant_fault)) {
    std::fprintf(stderr, "rayspec run: unknown fault '%s'\n", opt.plant_fault.c_str());
    return 2;
  }
  if (isProcessFault(opt.plant_fault) && opt.no_isolation) {
    std::fprintf(stderr, "rayspec run: the fault '%s' needs the device in a child process (no --no-isolation)\n",
                 opt.plant_fault.c_str());
    return 2;
  }
  if (!opt.plant_fault.empty()) std::printf("Planted fault: %s (test only)\n", opt.plant_fault.c_str());

  // Without isolation one device serves every case; with it each case's
  // child process creates its own (the parent never initialises Vulkan).
  std::unique_ptr<VulkanBackend> backend;
  std::string backend_error;
  if (!opt.no_device && opt.no_isolation) {
    VulkanOptions vopt;
    vopt.device_filter = opt.device;
    vopt.validation = validation;
    backend = VulkanBackend::create(vopt, &backend_error);
    if (backend) {
      info.device = backend->device().name + " (" + backend->device().driver_info + ")";
      info.validation = backend->validationEnabled();
      std::printf("Device: %s%s\n", info.device.c_str(),
                  info.validation ? ", validation layer on" : ", validation layer OFF");
    } else {
      info.device = "none";
      std::printf("Device: none (%s)\n", backend_error.c_str());
    }
  } else if (!opt.no_device) {
    info.validation = validation && validationLayerInstalled();
    std::printf("Device: each case in its own process (timeout %g s)%s\n", opt.timeout,
                info.validation ? ", validation layer on" : ", validation layer OFF");
  }
  if (!opt.no_model) std::printf("Model: embree, %s tier\n", opt.model_tier.c_str());
  if (opt.permute) std::printf("Permuted: primitives and instances, seed %llu\n", (unsigned long long)*opt.permute);

  Baseline baseline;
  if (!opt.baseline.empty()) {
    std::string baseline_error;
    baseline = loadBaseline(opt.baseline, &baseline_error);
    if (!baseline_error.empty()) {
      std::fprintf(stderr, "rayspec run: %s\n", baseline_error.c_str());
      return 2;
    }
    std::printf("Baseline: %s (%zu known results)\n", opt.baseline.c_str(), baseline.expected.size());
  }

  RunSummary summary(files.size());
  std::vector<std::pair<std::string, std::vector<std::string>>> case_rules;
  for (const CaseFile& f : files) {
    summary.starting(f.name);
    const auto start = std::chrono::steady_clock::now();
    ParseResult parsed = parseCaseFile(f.path, opt.cases_dir);
    CaseOutcome outcome;
    outcome.name = f.name;
    outcome.status = Status::Fail;
    std::string message;
    for (const CaseError& e : parsed.errors) message += (message.empty() ? "" : "\n  ") + e.format();
    if (parsed.value && message.empty() && !info.catalog.empty()) {
      const std::string unknown = unknownRules(*parsed.value, info.catalog);
      if (!unknown.empty()) message = f.path + ": rules: unknown rule label(s) " + unknown;
    }
    if (!parsed.value || !message.empty()) {
      outcome.headline = "Fail: case file error: " + message;
      outcome.verdict.add({Status::Fail, "case-file", message, {}, 0});
    } else {
      if (opt.permute) parsed.value = permuteCase(*parsed.value, *opt.permute).permuted;
      outcome = runOne(*parsed.value, opt, backend.get(), backend_error);
      case_rules.push_back({outcome.name, outcome.rules});
    }
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (info.device.empty() && !outcome.device_name.empty()) info.device = outcome.device_name;
    applyBaseline(baseline, outcome);
    summary.add(outcome);
    // The reports so far: a run cut short still leaves them.
    info.coverage = ruleCoverage(info.catalog, case_rules);
    const std::string err = writeReports(summary.outcomes(), info, opt.out);
    if (!err.empty()) std::fprintf(stderr, "%s\n", err.c_str());
  }
  if (backend)
    for (const std::string& m : backend->close()) summary.addTeardownError(m);
  info.teardown_errors = summary.teardownErrors();
  info.coverage = ruleCoverage(info.catalog, case_rules);
  summary.print();
  const std::string err = writeReports(summary.outcomes(), info, opt.out);
  if (!err.empty()) std::fprintf(stderr, "%s\n", err.c_str());
  std::printf("Reports: %s/report.html, results.csv, junit.xml, summary.json\n", opt.out.c_str());
  if (summary.failed()) return 1;
  if (files.size() == 1 && summary.allNotSupported()) return kExitNotSupported;
  return 0;
}

}  // namespace rayspec
