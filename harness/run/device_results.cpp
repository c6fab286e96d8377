#include "run/device_results.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "base/visible_text.h"
#include "base/whole_file.h"
#include "bundle/results_io.h"
#include "model/model_engine.h"
#include "report/outcome_json.h"
#include "results/content_hash.h"
#include "run/isolation.h"

namespace rayspec {
namespace fs = std::filesystem;

std::string savedBundleDir(const std::string& dir, const std::string& case_name) {
  return (fs::path(dir) / case_name / "device").string();
}

Result<void> checkCaseBundle(const Results& r, const std::string& bundle, const Case& c,
                             const Plan& plan) {
  const std::string json = bundle + "/results.json";
  if (r.case_name != c.name)
    return errorOf(ErrorKind::Harness,
                   json + ": the bundle is case '" + r.case_name + "', not '" + c.name + "'");
  if (r.case_hash == 0)
    return errorOf(ErrorKind::Harness, json +
                                           ": records no case_hash (saved by an older "
                                           "rayspec): run the case there again");
  if (r.case_hash != c.source_hash)
    return errorOf(ErrorKind::Harness,
                   json + ": case_hash " + contentHashText(r.case_hash) + ", but the case here (" +
                       c.file + ") hashes to " + contentHashText(c.source_hash) +
                       ": the case changed since it ran there (or --permute or --move differs); "
                       "run it there again");
  // A saved bundle holds the counters the case keeps, no others: a counter
  // it does not declare is not the answer to this case.
  for (const auto& [name, value] : r.counters)
    if (std::find(plan.counters.begin(), plan.counters.end(), name) == plan.counters.end())
      return errorOf(ErrorKind::Harness, json + ": counter '" + visibleText(name, 80) +
                                             "' is not one the case keeps (outputs.counters)");
  return {};
}

Result<Results> readCaseBundle(const std::string& bundle, const Case& c, const Plan& plan) {
  Result<Results> read = readResults(bundle);
  if (!read) return errorOf(ErrorKind::Harness, "saved results: " + read.error().format());
  RAYSPEC_TRY_VOID(checkCaseBundle(*read, bundle, c, plan));
  return read;
}

Result<Results> SavedDevice::run(const Case& c, const Plan& plan) {
  const std::string bundle = savedBundleDir(dir_, c.name);
  if (!fs::exists(fs::path(bundle) / "results.json")) {
    Results r;
    r.backend = name();
    r.case_name = c.name;
    r.setStatus(SideStatus::NotSupported, "no saved device results in " + bundle +
                                              ": the case did not run there, nothing was compared");
    return r;
  }
  return readCaseBundle(bundle, c, plan);
}

Result<void> deviceResultsError(const RunOptions& opt) {
  const std::string& dir = opt.device_results;
  if (dir.empty()) return {};
  const std::string what = "--device-results " + dir;
  if (!modelInThisBuild())
    return errorMessage(
        what + ": this run-only build has no model to judge by; judge where the full build is");
  if (opt.no_model)
    return errorMessage(what + " with --no-model: nothing to judge the saved results by");
  if (opt.no_device)
    return errorMessage(what + " with --no-device: the saved device results are the device side");
  if (!opt.device.empty())
    return errorMessage(what + " with --device: no device runs, the results were saved on one");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return errorMessage(what + ": not a folder");
  if (fs::weakly_canonical(dir, ec) == fs::weakly_canonical(opt.out, ec))
    return errorMessage(
        what +
        " is the --out folder: the run would remove the results it reads; give another --out");
  // The saved run did its cases by a variant (--through, --permute, --move):
  // they are judged by the same one only.
  if (fs::exists(fs::path(dir) / "summary.json", ec))
    if (const Result<SavedRun> saved = readSavedRun(dir);
        saved && saved->info.variant != runVariant(opt))
      return errorMessage(what + " ran its cases " + variantText(saved->info.variant) +
                          ", this run would judge them " + variantText(runVariant(opt)) +
                          ": give the same --through, --permute and --move");
  return {};
}

std::string savedDevices(const std::string& dir, const std::vector<CaseFile>& cases) {
  std::vector<std::string> devices;
  for (const CaseFile& c : cases) {
    const Result<std::string> text = readWholeFile(
        (fs::path(savedBundleDir(dir, c.name)) / "results.json").string(), kMaxResultsJsonBytes);
    if (!text) continue;
    const nlohmann::json j = nlohmann::json::parse(*text, nullptr, false);
    if (j.is_discarded() || !j.contains("device") || !j["device"].is_string()) continue;
    const std::string device = j["device"];
    if (!device.empty() && std::find(devices.begin(), devices.end(), device) == devices.end())
      devices.push_back(device);
  }
  std::string out;
  for (const std::string& d : devices) out += (out.empty() ? "" : ", ") + d;
  return out;
}

}  // namespace rayspec
