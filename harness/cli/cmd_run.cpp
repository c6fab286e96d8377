#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "case/parse_case.h"
#include "cli/case_discovery.h"
#include "cli/commands.h"
#include "cli/run_summary.h"
#include "compare/compare_results.h"
#include "model/model_backend.h"
#include "plan/plan.h"
#include "results/results_io.h"
#include "vulkan/vulkan_backend.h"

namespace rayspec {
namespace {

constexpr int kExitNotSupported = 77;  // ctest's SKIP_RETURN_CODE for a single case

bool validationLayerInstalled() {
  for (const char* dir : {"/usr/share/vulkan/explicit_layer.d", "/usr/local/share/vulkan/explicit_layer.d",
                          "/etc/vulkan/explicit_layer.d"})
    if (std::filesystem::exists(std::string(dir) + "/VkLayer_khronos_validation.json")) return true;
  return false;
}

// Runs one parsed case on the selected backends and compares.
CaseOutcome runOne(const Case& c, const RunOptions& opt, VulkanBackend* backend, const std::string& backend_error) {
  CaseOutcome out{c.name, Status::Pass, ""};
  const Plan plan = derivePlan(c);
  const std::string dir = opt.out + "/" + c.name;
  Results device, model;
  const bool want_device = !opt.no_device, want_model = !opt.no_model;
  if (want_device) {
    if (backend) {
      device = backend->run(c, plan);
    } else {
      device.backend = "vulkan";
      device.status = "NotSupported: " + backend_error;
    }
    device.case_name = c.name;
    out.device_seconds = device.seconds;
    const std::string err = writeResults(device, dir + "/device", plan.record_fields);
    if (!err.empty()) std::fprintf(stderr, "%s\n", err.c_str());
  }
  if (want_model) {
    ModelOptions mopt;
    mopt.tier = parseModelTier(opt.model_tier);
    mopt.threads = opt.threads;
    model = runOnModel(c, plan, mopt);
    model.case_name = c.name;
    out.model_seconds = model.seconds;
    const std::string err = writeResults(model, dir + "/model", plan.record_fields);
    if (!err.empty()) std::fprintf(stderr, "%s\n", err.c_str());
  }
  Verdict v;
  if (want_device && want_model) {
    v = compareResults(c, plan, device, model);
  } else {
    // One side only: its own status, validation errors included; never more than that.
    const Results& only = want_device ? device : model;
    v = backendVerdict(only);
    for (const std::string& m : only.validation_messages) v.add({Status::Fail, "validation", m, {}, 0});
  }
  out.status = v.status;
  out.headline = v.headline();
  out.verdict = v;
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

  std::unique_ptr<VulkanBackend> backend;
  std::string backend_error;
  if (!opt.no_device) {
    VulkanOptions vopt;
    vopt.device_filter = opt.device;
    vopt.validation = validation;
    backend = VulkanBackend::create(vopt, &backend_error);
    if (backend)
      std::printf("Device: %s (%s)%s\n", backend->device().name.c_str(), backend->device().driver_info.c_str(),
                  backend->validationEnabled() ? ", validation layer on" : ", validation layer OFF");
    else
      std::printf("Device: none (%s)\n", backend_error.c_str());
  }
  if (!opt.no_model) std::printf("Model: embree, %s tier\n", opt.model_tier.c_str());

  RunSummary summary(files.size());
  for (const CaseFile& f : files) {
    const auto start = std::chrono::steady_clock::now();
    ParseResult parsed = parseCaseFile(f.path, opt.cases_dir);
    CaseOutcome outcome{f.name, Status::Fail, ""};
    if (!parsed.value || !parsed.errors.empty()) {
      std::string message;
      for (const CaseError& e : parsed.errors) message += (message.empty() ? "" : "\n  ") + e.format();
      outcome.headline = "Fail: case file error: " + message;
    } else {
      outcome = runOne(*parsed.value, opt, backend.get(), backend_error);
    }
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    summary.add(outcome);
  }
  if (backend) {
    for (const std::string& m : backend->close()) summary.addTeardownError(m);
  }
  summary.print();
  const std::string err = summary.write(opt.out);
  if (!err.empty()) std::fprintf(stderr, "%s\n", err.c_str());
  if (summary.failed()) return 1;
  if (files.size() == 1 && summary.allNotSupported()) return kExitNotSupported;
  return 0;
}

}  // namespace rayspec
