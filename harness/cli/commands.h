// The subcommands of the rayspec command line.
#pragma once

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
  std::string rules_file = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";
};

struct ShowOptions {
  std::string case_file;
  bool no_glsl = false;
  bool vocabulary = false;
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";
};

int runDevices(const DevicesOptions& opt);
int runCases(const RunOptions& opt);
int runShow(const ShowOptions& opt);

}  // namespace rayspec
