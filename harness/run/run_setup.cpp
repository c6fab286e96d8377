#include "run/run_setup.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <optional>
#include <set>

#include "base/visible_text.h"
#include "report/outcome_json.h"
#include "report/rule_catalog.h"
#include "run/device_probe.h"
#include "run/device_results.h"
#include "run/fault_seam.h"
#include "run/run_loop.h"
#include "run/run_only.h"
#include "run/shard.h"

namespace rayspec {
namespace {

bool validationLayerInstalled() {
  if (const char* path = std::getenv("VK_LAYER_PATH"))
    if (std::filesystem::exists(std::string(path) + "/VkLayer_khronos_validation.json"))
      return true;
  for (const char* dir :
       {"/usr/share/vulkan/explicit_layer.d", "/usr/local/share/vulkan/explicit_layer.d",
        "/etc/vulkan/explicit_layer.d"})
    if (std::filesystem::exists(std::string(dir) + "/VkLayer_khronos_validation.json")) return true;
  return false;
}

std::string timeNow() {
  char text[64];
  const std::time_t t = std::time(nullptr);
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&t));
  return text;
}

std::vector<CaseFile> caseFiles(const RunOptions& opt) {
  if (opt.case_files.empty() && !opt.filters.empty())
    return findCasesAny(opt.cases_dir, opt.filters);
  if (opt.case_files.empty()) return findCases(opt.cases_dir, opt.filter);
  std::vector<CaseFile> files;
  for (const std::string& f : opt.case_files)
    for (CaseFile& c : caseFilesFor(f, opt.cases_dir)) files.push_back(std::move(c));
  checkCaseNames(files);
  return files;
}

// The shard asked for (--shard, else GoogleTest's variables), if any.
Result<std::optional<Shard>> chosenShard(const RunOptions& opt) {
  if (opt.shard.empty()) return shardFromEnvironment();
  Result<Shard> s = parseShard(opt.shard);
  if (!s) return s.error();
  return std::optional<Shard>(*s);
}

// --resume: what the run folder already holds must come from the same kind
// of run. The error: ErrorKind::Input, saying why not.
Result<void> resumeError(const SavedRun& saved, const RunInfo& info, const std::string& out,
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
    return errorMessage("--resume: " + out + " holds " + std::to_string(unselected) +
                        " case(s) this run does not select (" + first +
                        (unselected > 1 ? ", ..." : "") +
                        "): resume with the selection the run started with");
  if (saved.info.model_tier != info.model_tier)
    return errorMessage("--resume: " + out + " was run with model tier '" + saved.info.model_tier +
                        "', this run uses '" + info.model_tier + "'");
  if (saved.info.device != info.device)
    return errorMessage("--resume: " + out + " was run on '" + saved.info.device +
                        "', this run is on '" + info.device + "'");
  if (saved.info.variant != info.variant)
    return errorMessage("--resume: " + out + " ran its cases " + variantText(saved.info.variant) +
                        ", this run would run them " + variantText(info.variant));
  return {};
}

// Options that cannot work together: an ErrorKind::Input error.
Result<void> optionError(const RunOptions& opt) {
  if (!opt.no_validation && opt.strict_validation && !validationLayerInstalled())
    return errorMessage(
        "the Khronos validation layer is not installed (vulkan-validationlayers); run "
        "tools/setup.sh");
  if (opt.no_device && opt.no_model)
    return errorMessage("--no-device and --no-model: nothing would run");
  if (!parseModelTier(opt.model_tier))
    return errorMessage("model tier '" + opt.model_tier + "': the tiers are " +
                        namesJoined(enumNames<ModelTier>()));
  RAYSPEC_TRY_VOID(plantedFaultError(opt));
  return deviceResultsError(opt);
}

// A device probed in this process: the adapter every case will use.
DeviceProbe adapterInThisProcess(const VulkanOptions& vopt, ChosenDevice& chosen, RunInfo& info) {
  chosen.adapter = std::make_unique<VulkanAdapter>(vopt);
  info.validation = chosen.adapter->validationEnabled();
  return describeAdapter(*chosen.adapter);
}

// A device probed by a short child process (the parent never initialises
// Vulkan when cases are isolated).
DeviceProbe deviceInAChild(const RunOptions& opt, const VulkanOptions& vopt, RunInfo& info) {
  info.validation = vopt.validation && validationLayerInstalled();
  return probeDevice(vopt, ChildLimits{opt.timeout, opt.memory_limit});
}

// --device-results: the devices that saved the bundles.
ChosenDevice savedDevice(const RunOptions& opt, const std::vector<CaseFile>& files, RunInfo& info) {
  ChosenDevice chosen;
  info.device = savedDevices(opt.device_results, files);
  chosen.found = !info.device.empty();
  std::printf(
      "Device results saved in %s (%s); no device runs here\n",
      visibleLine(opt.device_results).c_str(),
      chosen.found ? visibleLine(info.device).c_str() : "none of these cases has a bundle there");
  return chosen;
}

}  // namespace

ModelTier checkedModelTier(const RunOptions& opt) {
  return parseModelTier(opt.model_tier).value_or(ModelTier::Exact);
}

int setupFailed(const Error& why) {
  std::fprintf(stderr, "rayspec run: %s\n", visibleLine(why.format()).c_str());
  return kExitSetup;
}

namespace {

// The glob, or the globs, --filter gave: "a/*' or 'b/*".
std::string filterText(const RunOptions& opt) {
  if (opt.filters.empty()) return opt.filter;
  std::string text;
  for (const std::string& g : opt.filters) text += (text.empty() ? "" : "' or '") + g;
  return text;
}

}  // namespace

Result<std::vector<CaseFile>> selectedCaseFiles(const RunOptions& opt) {
  std::vector<CaseFile> files = caseFiles(opt);
  if (files.empty())
    return errorMessage("no case matches '" + filterText(opt) + "' in " + opt.cases_dir);
  RAYSPEC_TRY_VOID(optionError(opt));
  return files;
}

Result<std::vector<CaseFile>> thisShard(const RunOptions& opt, std::vector<CaseFile> files) {
  const Result<std::optional<Shard>> chosen = chosenShard(opt);
  if (!chosen) return chosen.error();
  const std::optional<Shard>& shard = *chosen;
  if (!shard) return files;
  const size_t all = files.size();
  std::vector<CaseFile> mine;
  for (size_t i : shardPositions(all, *shard)) mine.push_back(std::move(files[i]));
  if (mine.empty())
    return errorMessage(shard->describe() + " holds no case (there are " + std::to_string(all) +
                        ")");
  std::printf("Shard: %s, %zu of %zu cases\n", shard->describe().c_str(), mine.size(), all);
  return mine;
}

RunInfo startRunInfo(const RunOptions& opt, size_t planned_cases) {
  RunInfo info;
  info.started = timeNow();
  info.model_tier = opt.no_model ? "none" : opt.model_tier;
  info.variant = runVariant(opt);
  info.planned_cases = planned_cases;
  info.interrupted = true;  // until the last case is done: a run killed before then stays marked
  if (Result<std::vector<Rule>> catalog = loadRuleCatalog(opt.rules_file))
    info.catalog = std::move(*catalog);
  else
    std::fprintf(stderr, "rayspec run: %s\n", catalog.error().format().c_str());
  if (!opt.plant_fault.empty())
    std::printf("Planted fault: %s (test only)\n", opt.plant_fault.c_str());
  return info;
}

Result<Baseline> loadRunBaseline(const RunOptions& opt) {
  return loadBaselineSet(opt.baseline, opt.flakes, opt.skips,
                         opt.through ? featurePathName(*opt.through) : "");
}

Result<ChosenDevice> chooseDevice(const RunOptions& opt, const std::vector<CaseFile>& files,
                                  const IcdSelection& icd, RunInfo& info) {
  if (!opt.device_results.empty()) return savedDevice(opt, files, info);
  ChosenDevice chosen;
  if (opt.no_device) return chosen;
  const VulkanOptions vopt = vulkanOptions(opt);
  const DeviceProbe probe =
      opt.no_isolation ? adapterInThisProcess(vopt, chosen, info) : deviceInAChild(opt, vopt, info);
  if (!probe.found) return errorMessage("no device to run on: " + probeFailure(probe));
  chosen.found = true;
  chosen.gpu = !probe.cpu;
  chosen.probed = probe.probed;
  info.device = probe.description;
  info.icd = !probe.icd.empty() || icd.files.size() != 1 ? probe.icd : icd.files[0];
  std::printf("Device: %s, ICD %s%s%s\n", visibleLine(info.device).c_str(),
              info.icd.empty() ? "unknown" : visibleLine(info.icd).c_str(),
              info.validation ? ", validation layer on" : ", validation layer OFF",
              opt.no_isolation ? ", in this process" : "");
  return chosen;
}

Result<std::map<std::string, CaseOutcome>> resumedCases(const RunOptions& opt, RunInfo& info,
                                                        const std::vector<CaseFile>& files) {
  std::map<std::string, CaseOutcome> earlier;
  if (!opt.resume) return earlier;
  Result<SavedRun> read = readSavedRun(opt.out);
  if (!read) return read.error();
  SavedRun& saved = *read;
  RAYSPEC_TRY_VOID(resumeError(saved, info, opt.out, files));
  info.started = saved.info.started;
  for (CaseOutcome& o : saved.outcomes) earlier[o.name] = std::move(o);
  std::printf("Resuming %s: %zu cases already ran\n", opt.out.c_str(), earlier.size());
  return earlier;
}

}  // namespace rayspec
