// `rayspec prove CASE_FILE...`: every rule a case claims proven by a planted
// fault (fault/prove_case.h, the proof behind the library's ctest
// fault/Cases/<family>), the model's exact tier standing for the device; a
// claim no fault breaks is hollow, printed with every fault tried. Nothing is
// written.
#pragma once

#include <string>
#include <vector>

#include "run/run_options.h"  // RAYSPEC_SOURCE_DIR

namespace rayspec {

struct ProveOptions {
  std::vector<std::string> files;                       // case files or sweep files, anywhere
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";  // names the files under it
  std::string rules_file = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";
  unsigned threads = 0;  // the model's (0: all cores)
  bool verbose = false;  // every fault's outcome, proven claims too
  // --device or --icd: a claim the model's faults leave hollow is tried on
  // this device with its rule's live faults (mutate/prove_live.h).
  bool live = false;
  RunOptions run;
};

// 0: every case proven; 1: a claim not proven (hollow, failing a legal
// device), or a case the model does not pass or whose verdict depends on the
// candidate order; 2: a file missing or not a case.
int runProve(const ProveOptions& opt);

}  // namespace rayspec
