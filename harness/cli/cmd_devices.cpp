// `rayspec devices`: every driver manifest the loader would read, each probed
// alone in a child process (run/icd_probe.h), with its devices (identity:
// conformance version, driver ID, UUIDs), whether each can run the cases and
// why not, the validation layer runs would load, and of the usable ones the
// options that select one, the library cases they cannot run with the
// missing feature that keeps them (run/library_support.h) and their ray
// tracing limits.
#include <cstdio>

#include "base/shell_word.h"
#include "base/visible_text.h"
#include "cli/commands.h"
#include "cli/limits_check.h"
#include "run/device_description.h"
#include "run/icd_probe.h"
#include "run/library_support.h"
#include "vulkan/device_usability.h"
#include "vulkan/icd_environment.h"

namespace rayspec {
namespace {

// A value of DeviceInfo as `rayspec devices` prints it.
std::string deviceValueText(uint32_t v) {
  return std::to_string(v);
}
std::string deviceValueText(uint64_t v) {
  return std::to_string(v);
}
std::string deviceValueText(bool v) {
  return v ? "yes" : "no";
}
std::string deviceValueText(const std::string& v) {
  return v;
}
std::string deviceValueText(const DeviceLaunchSize& v) {
  return std::to_string(v[0]) + " x " + std::to_string(v[1]) + " x " + std::to_string(v[2]);
}
std::string deviceValueText(const std::vector<std::string>& v) {
  std::string text;
  for (const std::string& s : v) text += (text.empty() ? "" : " ") + s;
  return text.empty() ? "none" : text;
}

// One line of the limits; none for a field without a label.
void printDeviceField(const char* label, const std::string& value) {
  if (label) std::printf("        %-30s %s\n", label, visibleLine(value).c_str());
}

// The rows of vulkan/device_info_fields.h that have a label, in its order.
void printLimits(const DeviceInfo& d) {
#define RAYSPEC_DEVICE_INFO_LINE(type, member, key, label, meaning) \
  printDeviceField(label, deviceValueText(d.member));
  RAYSPEC_DEVICE_INFO_FIELDS(RAYSPEC_DEVICE_INFO_LINE)
#undef RAYSPEC_DEVICE_INFO_LINE
}

// What --check-limits adds: the baseline of known violations and the tally.
struct LimitsRun {
  bool check = false;
  Baseline baseline;
  LimitsVerdict verdict;
};

// The library's cases, read once for the first usable device, and the
// validation layer a run would have on.
struct LibraryView {
  uint32_t validation_layer = 0;
  bool loaded = false;
  std::vector<LibraryCase> cases;
};

// A usable device: the library cases it cannot run, and which missing
// feature keeps how many of them.
void printLibrarySupport(const DeviceInfo& d, LibraryView& library) {
  if (!library.loaded) library.cases = libraryCases(RAYSPEC_SOURCE_DIR "/cases");
  library.loaded = true;
  for (const std::string& line :
       librarySupportLines(librarySupport(library.cases, d, library.validation_layer)))
    std::printf("        %s\n", line.c_str());
}

// One manifest's devices; returns how many are usable.
int printProbe(const IcdProbe& p, LimitsRun& limits, LibraryView& library) {
  std::printf("ICD %s (library %s%s%s)\n", visibleLine(p.manifest.path).c_str(),
              visibleLine(p.manifest.library_path).c_str(),
              p.manifest.api_version.empty() ? "" : ", Vulkan ",
              visibleLine(p.manifest.api_version).c_str());
  if (p.devices.empty())
    std::printf("    NOT USABLE: %s\n",
                p.failure.empty() ? "no physical device" : visibleLine(p.failure).c_str());
  int usable = 0;
  for (const DeviceInfo& d : p.devices) {
    const DeviceUsability u = deviceUsability(d);
    std::printf("    [%u] %s: %s%s\n", d.index, visibleLine(d.name).c_str(),
                u == DeviceUsability::Usable ? "USABLE" : "NOT USABLE: ",
                u == DeviceUsability::Usable ? "" : usabilityReason(u, d).c_str());
    std::printf("        driver %s (%s), Vulkan %s\n",
                d.driver_name.empty() ? "?" : visibleLine(d.driver_name).c_str(),
                visibleLine(d.driver_info).c_str(), visibleLine(d.api_version).c_str());
    for (const std::string& line : deviceIdentityLines(d))
      std::printf("        %s\n", visibleLine(line).c_str());
    if (u != DeviceUsability::Usable) continue;
    ++usable;
    std::printf("        select: --icd %s --device %s\n",
                visibleLine(shellWord(p.manifest.path)).c_str(),
                visibleLine(shellWord(d.name)).c_str());
    printLibrarySupport(d, library);
    printLimits(d);
    if (!limits.check) continue;
    const LimitsVerdict v = printLimitChecks(d, limits.baseline);
    limits.verdict.violations += v.violations;
    limits.verdict.expected += v.expected;
    limits.verdict.unexpected += v.unexpected;
    limits.verdict.unexpected_passes += v.unexpected_passes;
    limits.verdict.unexpected_limits.insert(limits.verdict.unexpected_limits.end(),
                                            v.unexpected_limits.begin(), v.unexpected_limits.end());
  }
  return usable;
}

// The folder of the limits baselines rayspec keeps.
const char* const kLimitsBaselines = RAYSPEC_SOURCE_DIR "/references/baselines";

// After violations no baseline given expects: the kept baseline that lists
// them all (they are that driver's known ones) and how to pass it, or how to
// write one.
void printBaselineHint(const LimitsVerdict& v) {
  if (v.unexpected == 0) return;
  const std::vector<std::string> known = baselinesListing(kLimitsBaselines, v.unexpected_limits);
  if (!known.empty()) {
    std::printf(
        "Known violations: %s lists %s as this driver's (a baseline of known limit "
        "violations); judge against it with\n  rayspec devices --check-limits --baseline %s\n",
        visibleLine(known.front()).c_str(), v.unexpected == 1 ? "it" : "them all",
        visibleLine(shellWord(known.front())).c_str());
    return;
  }
  std::printf(
      "No baseline in %s lists %s. A driver's known violations go in a baseline of "
      "`limits/<limit>,Fail` lines (as lavapipe-limits.csv there), passed with --baseline FILE.\n",
      kLimitsBaselines, v.unexpected == 1 ? "it" : "them all");
}

}  // namespace

int runDevices(const DevicesOptions& opt) {
  const IcdSelection selection = useIcdFiles(opt.icd_files);
  for (const std::string& note : selection.notes)
    std::fprintf(stderr, "rayspec devices: %s\n", note.c_str());
  if (!selection.error.empty()) {
    std::fprintf(stderr, "rayspec devices: %s\n", selection.error.c_str());
    return 2;
  }
  const IcdSearch search = findIcdManifests();
  std::string places;
  for (const std::string& p : search.places) places += (places.empty() ? "" : ", ") + p;
  std::printf("Driver manifests from %s%s: %s\n\n", icdSourceName(search.source).c_str(),
              opt.icd_files.empty() ? "" : " (--icd)", places.c_str());
  const uint32_t layer = installedValidationLayer();
  std::printf("%s\n\n", validationLayerLine(layer, opt.no_validation).c_str());
  LimitsRun limits{opt.check_limits, {}, {}};
  LibraryView library{opt.no_validation ? 0 : layer, false, {}};
  if (!opt.limits_baseline.empty()) {
    Result<Baseline> b = loadLimitsBaseline(opt.limits_baseline);
    if (!b) {
      std::fprintf(stderr, "rayspec devices: %s\n", b.error().format().c_str());
      return 2;
    }
    limits.baseline = std::move(*b);
  }
  int usable = 0;
  for (const IcdManifest& m : search.manifests)
    usable += printProbe(probeIcd(m, ChildLimits{kProbeSeconds, 0}), limits, library);
  for (const std::string& e : search.errors)
    std::printf("NOT USABLE: %s\n", visibleLine(e).c_str());
  const size_t manifests = search.manifests.size() + search.errors.size();
  if (usable == 0) {
    std::printf(
        "\nNo usable device (Vulkan 1.2 with ray tracing pipelines and acceleration structures) "
        "through %zu driver manifest%s.\n",
        manifests, manifests == 1 ? "" : "s");
    return 1;
  }
  std::printf("\n%d usable device%s through %zu driver manifest%s.\n", usable,
              usable == 1 ? "" : "s", manifests, manifests == 1 ? "" : "s");
  if (!limits.check) return 0;
  const LimitsVerdict& v = limits.verdict;
  std::printf(
      "Required limits: %d violation%s (%d expected by the baseline, %d unexpected), %d "
      "unexpected pass%s.\n",
      v.violations, v.violations == 1 ? "" : "s", v.expected, v.unexpected, v.unexpected_passes,
      v.unexpected_passes == 1 ? "" : "es");
  printBaselineHint(v);
  return v.unexpected > 0 || v.unexpected_passes > 0 ? 1 : 0;
}

}  // namespace rayspec
