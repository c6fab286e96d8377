#include "run/run_loop.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <set>
#include <filesystem>
#include <memory>
#include <optional>

#include "fault/planted_fault.h"
#include "metamorphic/motion_spec.h"
#include "metamorphic/permute_case.h"
#include "report/baseline_gate.h"
#include "report/outcome_json.h"
#include "report/rule_catalog.h"
#include "run/cache_dir.h"
#include "run/case_steps.h"
#include "run/device_probe.h"
#include "run/device_results.h"
#include "run/interrupt.h"
#include "run/model_adapter.h"
#include "run/shard.h"
#include "run/run_only.h"
#include "run/vulkan_adapter.h"
#include "vulkan/device_errors.h"
#include "vulkan/icd_environment.h"

namespace rayspec {
namespace {

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

std::vector<CaseFile> caseFiles(const RunOptions& opt) {
  if (opt.case_files.empty() && !opt.filters.empty()) return findCasesAny(opt.cases_dir, opt.filters);
  if (opt.case_files.empty()) return findCases(opt.cases_dir, opt.filter);
  std::vector<CaseFile> files;
  for (const std::string& f : opt.case_files)
    for (CaseFile& c : caseFilesFor(f, opt.cases_dir)) files.push_back(std::move(c));
  checkCaseNames(files);
  return files;
}

// --move and a case it cannot move exactly: NotSupported, saying why (the
// case's verdict under the motion is unknown, never a pass).
CaseOutcome notMovedOutcome(const std::string& name, const std::string& why) {
  CaseOutcome o;
  o.name = name;
  o.verdict.add({Status::NotSupported, "move", "not run: --move cannot move this case exactly: " + why, {}, 0});
  o.status = o.verdict.status;
  o.headline = o.verdict.headline();
  o.baseline = BaselineMatch::Skipped;  // not run: the baseline's expectation is neither met nor broken
  o.baseline_note = "not run under --move";
  return o;
}

// The shard asked for (--shard, else GoogleTest's variables), if any.
std::optional<Shard> chosenShard(const RunOptions& opt, std::string* error) {
  if (!opt.shard.empty()) return parseShard(opt.shard, error);
  return shardFromEnvironment(error);
}

// --resume: what the run folder already holds must come from the same kind
// of run. The message, or "".
std::string resumeError(const SavedRun& saved, const RunInfo& info, const std::string& out,
                        const std::vector<CaseFile>& files) {
  // Every case the folder holds must be selected again, or --resume would
  // drop it from results.csv and summary.json.
  std::set<std::string> selected;
  for (const CaseFile& f : files) selected.insert(f.name);
  size_t unselected = 0;
  std::string first;
  for (const CaseOutcome& o : saved.outcomes)
    if (!selected.count(o.name) && unselected++ == 0) first = o.name;
  if (unselected)
    return "--resume: " + out + " holds " + std::to_string(unselected) + " case(s) this run does not select (" +
           first + (unselected > 1 ? ", ..." : "") + "): resume with the selection the run started with";
  if (saved.info.model_tier != info.model_tier)
    return "--resume: " + out + " was run with model tier '" + saved.info.model_tier + "', this run uses '" +
           info.model_tier + "'";
  if (saved.info.device != info.device)
    return "--resume: " + out + " was run on '" + saved.info.device + "', this run is on '" + info.device + "'";
  return {};
}

// Options that cannot work together; the message, or "".
std::string optionError(const RunOptions& opt) {
  if (!opt.no_validation && opt.strict_validation && !validationLayerInstalled())
    return "the Khronos validation layer is not installed (vulkan-validationlayers); run tools/setup.sh";
  if (!opt.plant_fault.empty() && !isFaultName(opt.plant_fault) && !deviceErrorFault(opt.plant_fault))
    return "unknown fault '" + opt.plant_fault + "'";
  if (isProcessFault(opt.plant_fault) && opt.no_isolation)
    return "the fault '" + opt.plant_fault + "' needs the device in a child process (no --no-isolation)";
  if (opt.no_device && opt.no_model) return "--no-device and --no-model: nothing would run";
  if (std::string e = runOnlyError(opt); !e.empty()) return e;
  return deviceResultsError(opt);
}

}  // namespace

int runCases(const RunOptions& requested) {
  const RunOptions opt = optionsForThisBuild(requested);
  std::vector<CaseFile> files = caseFiles(opt);
  if (files.empty()) {
    std::fprintf(stderr, "rayspec run: no case matches '%s' in %s\n", opt.filter.c_str(), opt.cases_dir.c_str());
    return kExitSetup;
  }
  if (const std::string err = optionError(opt); !err.empty()) {
    std::fprintf(stderr, "rayspec run: %s\n", err.c_str());
    return kExitSetup;
  }
  const IcdSelection icd = useIcdFiles(opt.icd_files);  // before any Vulkan call; children inherit it
  for (const std::string& note : icd.notes) std::fprintf(stderr, "rayspec run: %s\n", note.c_str());
  if (!icd.error.empty()) {
    std::fprintf(stderr, "rayspec run: %s\n", icd.error.c_str());
    return kExitSetup;
  }
  std::string shard_error;
  const std::optional<Shard> shard = chosenShard(opt, &shard_error);
  if (!shard_error.empty()) {
    std::fprintf(stderr, "rayspec run: %s\n", shard_error.c_str());
    return kExitSetup;
  }
  if (shard) {
    const size_t all = files.size();
    std::vector<CaseFile> mine;
    for (size_t i : shardPositions(all, *shard)) mine.push_back(std::move(files[i]));
    files = std::move(mine);
    if (files.empty()) {
      std::fprintf(stderr, "rayspec run: %s holds no case (there are %zu)\n", shard->describe().c_str(), all);
      return kExitSetup;
    }
    std::printf("Shard: %s, %zu of %zu cases\n", shard->describe().c_str(), files.size(), all);
  }
  RunInfo info;
  info.started = now();
  info.model_tier = opt.no_model ? "none" : opt.model_tier;
  info.planned_cases = files.size();
  info.interrupted = true;  // until the last case is done: a run killed before then stays marked
  std::string catalog_error;
  info.catalog = loadRuleCatalog(opt.rules_file, &catalog_error);
  if (!catalog_error.empty()) std::fprintf(stderr, "rayspec run: %s\n", catalog_error.c_str());
  if (!opt.plant_fault.empty()) std::printf("Planted fault: %s (test only)\n", opt.plant_fault.c_str());

  std::string baseline_error;
  const Baseline baseline = loadBaselineSet(opt.baseline, opt.flakes, opt.skips, &baseline_error);
  if (!baseline_error.empty()) {
    std::fprintf(stderr, "rayspec run: %s\n", baseline_error.c_str());
    return kExitSetup;
  }
  info.baseline = baseline.file;

  // The device must exist before any case runs. Isolated, the parent never
  // initialises Vulkan: a short child process looks; without isolation one
  // device serves every case.
  VulkanOptions vopt;
  vopt.device_filter = opt.device;
  vopt.validation = !opt.no_validation;
  std::unique_ptr<VulkanAdapter> device;
  std::unique_ptr<ModelAdapter> model;
  bool device_found = false;
  if (!opt.device_results.empty()) {
    info.device = savedDevices(opt.device_results, files);
    device_found = !info.device.empty();
    std::printf("Device results saved in %s (%s); no device runs here\n", opt.device_results.c_str(),
                device_found ? info.device.c_str() : "none of these cases has a bundle there");
  } else if (!opt.no_device) {
    DeviceProbe probe;
    if (opt.no_isolation) {
      device = std::make_unique<VulkanAdapter>(vopt);
      probe = describeAdapter(*device);
      info.validation = device->validationEnabled();
    } else {
      VulkanOptions quick = vopt;
      quick.validation = false;  // only whether a device matches
      probe = probeDevice(quick, ChildLimits{opt.timeout, opt.memory_limit});
      info.validation = vopt.validation && validationLayerInstalled();
    }
    if (!probe.found) {
      std::fprintf(stderr, "rayspec run: no device to run on: %s\n", probeFailure(probe).c_str());
      return kExitSetup;
    }
    device_found = true;
    info.device = probe.description;
    info.icd = !probe.icd.empty() || icd.files.size() != 1 ? probe.icd : icd.files[0];
    std::printf("Device: %s, ICD %s%s%s\n", info.device.c_str(), info.icd.empty() ? "unknown" : info.icd.c_str(),
                info.validation ? ", validation layer on" : ", validation layer OFF",
                opt.no_isolation ? ", in this process" : "");
  }
  if (!opt.no_model) {
    if (opt.no_isolation) model = std::make_unique<ModelAdapter>(ModelOptions{parseModelTier(opt.model_tier), opt.threads});
    std::printf("Model: embree, %s tier\n", opt.model_tier.c_str());
  }
  if (opt.permute) std::printf("Permuted: primitives and instances, seed %llu\n", (unsigned long long)*opt.permute);
  if (opt.move)
    std::printf("Moved: every case by the rigid motion %s (a case it cannot move exactly is NotSupported)\n",
                motionSpecText(*opt.move).c_str());
  if (!opt.no_isolation)
    std::printf("Each case side in its own process: timeout %g s, memory limit %s\n", opt.timeout,
                opt.memory_limit ? formatBytes(opt.memory_limit).c_str() : "none");
  if (!baseline.file.empty()) {
    std::printf("Baseline: %s (%zu known results)\n", baseline.file.c_str(), baseline.expected.size());
    std::vector<std::string> library;
    for (const CaseFile& f : findCases(opt.cases_dir, "*")) library.push_back(f.name);
    for (const std::string& w : unknownEntries(baseline, library)) std::printf("Baseline warning: %s\n", w.c_str());
  }
  if (!baseline.flakes_file.empty())
    std::printf("Flakes: %s (%zu patterns)\n", baseline.flakes_file.c_str(), baseline.flakes.size());
  if (!baseline.skips_file.empty())
    std::printf("Skips: %s (%zu patterns)\n", baseline.skips_file.c_str(), baseline.skips.size());
  std::map<std::string, CaseOutcome> earlier;  // --resume: the cases the folder already has
  if (opt.resume) {
    std::string error;
    SavedRun saved = readSavedRun(opt.out, &error);
    if (error.empty()) error = resumeError(saved, info, opt.out, files);
    if (!error.empty()) {
      std::fprintf(stderr, "rayspec run: %s\n", error.c_str());
      return kExitSetup;
    }
    info.started = saved.info.started;
    for (CaseOutcome& o : saved.outcomes) earlier[o.name] = std::move(o);
    std::printf("Resuming %s: %zu cases already ran\n", opt.out.c_str(), earlier.size());
  }

  useCacheDir(opt.cache_dir);  // before the first fork: every case process inherits it
  catchInterrupts();
  const CaseRunner runner(opt, device.get(), model.get());
  // Unknown rule labels are case-file errors at their line:col (the parser checks them).
  const std::vector<std::string> labels = ruleLabels(info.catalog);
  RunSummary summary(files.size());
  std::vector<std::pair<std::string, std::vector<std::string>>> case_rules;
  for (const CaseFile& f : files) {
    if (interruptSignal()) break;
    if (auto it = earlier.find(f.name); it != earlier.end()) {
      case_rules.push_back({f.name, it->second.rules});
      summary.add(it->second);  // ran before: kept as it was judged
      continue;
    }
    summary.starting(f.name);
    const auto start = std::chrono::steady_clock::now();
    bool interrupted = false;
    CaseOutcome outcome;
    if (const NamePattern* skip = findPattern(baseline.skips, f.name)) {
      outcome = skippedOutcome(f.name, *skip);
    } else {
      StepCosts parse_cost;
      StepTimer parse_time(parse_cost, CostStep::Parse);
      const ParseResult parsed = loadCase(f, opt.cases_dir, labels.empty() ? nullptr : &labels);
      parse_time.stop();
      if (std::optional<CaseOutcome> error = caseFileError(f, parsed)) {
        outcome = *error;
        applyBaseline(baseline, outcome);
      } else {
        std::optional<Case> changed;  // --permute, --move: the case as it runs
        if (opt.permute) changed = permuteCase(*parsed.value, *opt.permute).permuted;
        std::string not_moved;
        if (opt.move) changed = moveCase(changed ? *changed : *parsed.value, *opt.move, &not_moved, MoveScope::Verdict);
        const Case& c = changed ? *changed : *parsed.value;
        if (opt.move && !changed) {
          outcome = notMovedOutcome(f.name, not_moved);
        } else {
          outcome = guardCase(c.name, c.rules, [&] { return runner.run(c, &interrupted); });
          if (interrupted) break;
          outcome.cost[CostSide::Parent] += parse_cost;
          case_rules.push_back({c.name, c.rules});
          if (applyBaseline(baseline, outcome)) {
            // An unexpected failure: once more, into <case>/rerun, to tell a flake.
            std::printf("        unexpected %s: running it again\n", statusName(outcome.status));
            const CaseOutcome again =
                guardCase(c.name, c.rules, [&] { return runner.run(c, &interrupted, "/rerun"); });
            if (interrupted) break;
            applyRerun(outcome, again);
          }
        }
      }
    }
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    info.coverage = ruleCoverage(info.catalog, case_rules);
    if (summary.outcomes().size() + 1 == files.size()) info.interrupted = interruptSignal() != 0;
    reportCase(outcome, baseline, info, opt.out, summary);  // a run cut short still leaves its reports
  }
  if (device)
    for (const std::string& m : device->close()) summary.addTeardownError(m);
  info.teardown_errors = summary.teardownErrors();
  info.coverage = ruleCoverage(info.catalog, case_rules);
  info.interrupted = summary.outcomes().size() < files.size();
  summary.print();
  if (info.interrupted)
    std::printf("INTERRUPTED: %zu of %zu cases ran\n", summary.outcomes().size(), files.size());
  if (const std::string err = writeReports(summary.outcomes(), info, opt.out); !err.empty())
    std::fprintf(stderr, "%s\n", err.c_str());
  std::printf("Reports: %s/report.html, results.csv, junit.xml, summary.json\n", opt.out.c_str());
  const int status = runExitStatus(summary, files.size(), device_found, interruptSignal());
  if (status == kExitNothingCompared) std::fprintf(stderr, "rayspec run: nothing was compared: every case is NotSupported\n");
  return status;
}

int runExitStatus(const RunSummary& summary, size_t planned, bool device_found, int signal) {
  if (signal) return 128 + signal;
  if (summary.failed()) return kExitFailing;
  if (summary.allNotSupported() || summary.outcomes().empty())
    return planned == 1 && device_found && !summary.outcomes().empty() ? kExitNotSupported : kExitNothingCompared;
  return kExitPass;
}

}  // namespace rayspec
