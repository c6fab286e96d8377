// `rayspec accuracy`: two sets of cases (ordinary, hard) run on the model in
// each tier and on the device beside the exact tier (tiers/tier_runs.h, into
// OUT/runs/<set>/<tier>), plus other devices' saved run folders; then per
// set and source the trace time per million rays (each bundle's own
// model_trace or trace step, results/step_cost.h) and the disagreements
// with the model's exact tier ray by ray (accuracy/ray_disagreements.h), as
// OUT/accuracy.txt, accuracy.json and accuracy.png.
#pragma once

#include <string>
#include <vector>

#include "run/run_options.h"

namespace rayspec {

// The default ordinary set: families whose cases lavapipe passes
// (references/baselines/lavapipe.csv lists none of them) with many rays per
// case, the 1M-ray mixed scene first; small enough that the whole command
// stays within two minutes on a 2-core machine.
inline const std::vector<std::string> kDefaultOrdinary = {"model/*", "anyhit/*", "results/*",
                                                          "builtins/closest-hit-and-miss",
                                                          "intersection/sphere-both-roots"};
inline const std::vector<std::string> kDefaultHard = {"precision/*", "watertight/*", "stability/*"};

struct AccuracyOptions {
  RunOptions run;  // device, cases folder, limits of the runs (filter and out are set per run)
  std::string out = "rayspec-accuracy";
  std::vector<std::string> ordinary = kDefaultOrdinary;  // globs
  std::vector<std::string> hard = kDefaultHard;          // globs
  std::vector<std::string> tiers = {"fast", "robust", "exact"};
  // Run folders of other devices (a run-only binary's `rayspec run`): their
  // DIR/<case>/device bundles are compared too, one source each.
  std::vector<std::string> saved_devices;
};

// Exit status: 0 when the report was written; 1 when a report file could
// not be written; 2 when nothing ran (no case in either set, bad options,
// no device); 128 + the signal when interrupted.
int runAccuracy(const AccuracyOptions& opt);

}  // namespace rayspec
