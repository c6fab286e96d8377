// `rayspec fuzz`: cases generated from consecutive seeds (fuzz/generate_case.h)
// into OUT/cases/fuzz/seed-<seed>.yaml, run in batches by the run loop of
// `rayspec run` (run/run_loop.h: its long-lived workers, its judgement)
// into OUT/runs/batch-<n>, each outcome tallied (fuzz/fuzz_tally.h); the
// first case of each finding's signature kept as
// OUT/findings/<signature>/{case.yaml, report.md}, and OUT/fuzz.txt
// rewritten after every batch. With --reduce, each new signature's case is
// then reduced by `rayspec reduce` (reduce/reduce_case.h) into
// OUT/findings/<signature>/reduce/, its reduced.yaml copied beside case.yaml.
// With --fault-matrix, every rule-breaking planted fault is planted in each
// passing case's device results until a case finds it
// (mutate/fault_matrix.h), OUT/fault-matrix.txt rewritten after every batch.
#pragma once

#include <cstdint>
#include <string>

#include "fuzz/generator_features.h"
#include "run/case_check.h"
#include "run/run_options.h"

namespace rayspec {

struct FuzzOptions {
  uint64_t seed = 1;   // the first seed
  size_t cases = 0;    // --cases: this many (0: by --minutes)
  double minutes = 0;  // --minutes: batches until this much time has passed
  size_t batch = 16;   // cases a run of the run loop
  std::string out = "rayspec-fuzz";
  size_t reduce = 0;           // --reduce: attempts to reduce each new signature's case (0: none)
  std::string known;           // --known: known bug classes (fuzz/known_classes.h); "" none
  bool generate_only = false;  // --generate-only: write OUT/cases and stop (a device elsewhere
                               // runs them; --device-results judges what it saved)
  bool fault_matrix = false;   // --fault-matrix: OUT/fault-matrix.txt
  GeneratorFeatures allowed;   // --without: device features the cases leave out
  RunOptions run;              // the device, the model, --through, --plant-fault, --device-results
  // --saved-cases (with --device-results): the cases folder the saved device
  // run ran (--generate-only's OUT/cases), whose texts are judged
  // (fuzz/saved_cases.h) instead of the generator's here.
  std::string saved_cases;
  // Each generated case held to every legal device before it runs (as `rayspec
  // run` holds a case outside the library): a case one would fail is refused
  // ("not-portable"), never a finding. None: unchecked.
  CaseCheck check;
};

// 0: nothing found but known classes (or, with --generate-only, the cases
// written); 1: new findings (OUT/fuzz.txt lists them); 2: bad options,
// nothing could run, or a seed's saved case missing or not the one its
// bundle ran (each named on stderr; the other seeds judged); 128 + a signal
// that stopped it.
int runFuzz(const FuzzOptions& opt);

}  // namespace rayspec
