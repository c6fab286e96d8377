// The subcommands of the rayspec command line.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rayspec {

#ifndef RAYSPEC_SOURCE_DIR
#define RAYSPEC_SOURCE_DIR "."
#endif

struct DevicesOptions {
  bool no_validation = false;
};

struct RunOptions {
  std::string device;
  std::string filter = "*";
  std::string out = "rayspec-results";
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";
  std::vector<std::string> case_files;
  std::string model_tier = "exact";
  bool no_model = false;
  bool no_device = false;
  bool no_validation = false;
  bool strict_validation = false;
  unsigned threads = 0;
  double timeout = 120.0;        // seconds per case's device side (isolated)
  bool no_isolation = false;     // run the device in this process (one VkDevice for all cases)
  std::string plant_fault;       // test only: fault/planted_fault.h
  std::string plant_fault_in = "*";  // only in cases whose name matches this glob
  std::string rules_file = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";
  std::string baseline;          // known failures of this driver (report/baseline.h)
  std::optional<uint64_t> permute;  // run each case with primitives and instances permuted (metamorphic/)
};

struct ShowOptions {
  std::string case_file;
  bool no_glsl = false;
  bool vocabulary = false;
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";
};

struct CompareOptions {
  std::string a, b;              // results bundles or run folders
  std::string out = "rayspec-compare";
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";
  std::string rules_file = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";
};

int runDevices(const DevicesOptions& opt);
int runCases(const RunOptions& opt);
int runShow(const ShowOptions& opt);
int runCompare(const CompareOptions& opt);

}  // namespace rayspec
