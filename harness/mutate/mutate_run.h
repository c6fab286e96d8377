// `rayspec mutate RUN_DIR`: every case of a saved device run (RUN_DIR/<case>/
// device, as `rayspec run --out` or a run-only build writes it) judged
// against the model run here under every generic mutant; the kill matrix in
// OUT/mutate.txt and OUT/mutate.json.
#pragma once

#include <string>

namespace rayspec {

struct MutateOptions {
  std::string run_dir;
  std::string out = "rayspec-mutate";
  std::string cases_dir;
  std::string filter = "*";
  unsigned threads = 0;
};

// 0: every judged case killed the null device and every survivor has a legal
// reason; 1: a hole (or no case judged); kExitSetup-style 2 on bad options.
int runMutate(const MutateOptions& opt);

}  // namespace rayspec
