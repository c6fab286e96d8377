// The subcommands of the rayspec command line. `run` is run/run_loop.h
// (runCases with run/run_options.h); the others are here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "library/case_discovery.h"
#include "run/run_options.h"  // RAYSPEC_SOURCE_DIR

namespace rayspec {

struct DevicesOptions {
  bool no_validation = false;
  std::vector<std::string> icd_files;  // --icd: probe only these driver manifests
  bool check_limits = false;           // --check-limits: each usable device's required limits
  std::string limits_baseline;         // --baseline: the limits a driver is known to break
};

struct ShowOptions {
  std::string case_file;
  bool no_glsl = false;
  bool no_model = false;  // no model expectations, no portability check
  bool vocabulary = false;
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";
};

struct CompareOptions {
  std::string a, b;  // results bundles or run folders
  std::string out = "rayspec-compare";
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";
  std::string rules_file = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";
  bool brief = false;  // --brief (kBriefHelp)
};

struct ListOptions {
  bool rules = false;    // rule -> cases instead of case -> rules
  bool cts_map = false;  // docs/cts-map.md with its tables made from references/cts-map.yaml
  std::string cts_map_file = RAYSPEC_SOURCE_DIR "/references/cts-map.yaml";
  std::string cts_doc = RAYSPEC_SOURCE_DIR "/docs/cts-map.md";
  std::string filter = "*";
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";
  std::string rules_file = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";
};

struct CompileOptions {
  std::string filter = "*";
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";
  std::string cache_dir = defaultCacheDir();
};

struct MergeOptions {
  std::vector<std::string> dirs;  // run folders to join
  std::string out = "rayspec-merged";
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";  // the cases their bundles are judged by
  std::string baseline, flakes, skips;
  std::string rules_file = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";
  bool brief = false;  // --brief (kBriefHelp)
};
inline constexpr const char* kBriefHelp =
    "Print only the cases that fail the run as they end, and only them in the summary (the counts "
    "stay; every case is in the reports)";
inline constexpr const char* kIcdOptionHelp =
    "Vulkan driver manifest (ICD JSON) the loader may load; repeat it or separate files with ':'. "
    "Sets VK_DRIVER_FILES and VK_ICD_FILENAMES, overriding the environment's";

inline constexpr const char* kPlantFaultHelp =
    "Test only: corrupt the device's results in a known way, standing in for a wrong device "
    "(`rayspec faults` lists every fault with the rules it breaks)";

int runDevices(const DevicesOptions& opt);
int runShow(const ShowOptions& opt);
// The case a `show` or `export` argument names: a case file (a sweep file:
// its first variant, the others listed after "showing" or "exporting", the
// verb), or a case name under cases_dir.
std::optional<CaseFile> caseToShow(const std::string& given, const std::string& cases_dir,
                                   const char* verb);
int runList(const ListOptions& opt);
int runCtsMap(const ListOptions& opt);  // `rayspec list --cts-map`
int runCompile(const CompileOptions& opt);
int runCompare(const CompareOptions& opt);
int runMerge(const MergeOptions& opt);

}  // namespace rayspec
