// `rayspec stability`: the stability families (cases/stability/, sweeps with
// a `magnitude` parameter) run on the device and on the model in each tier,
// through `rayspec run`'s own machinery (run/run_loop.h: child processes,
// results bundles); then each run's leaks and double hits per family and
// magnitude (stability/leak_counts.h) as OUT/stability.txt, stability.json
// and stability.png.
#pragma once

#include <string>
#include <vector>

#include "run/run_options.h"

namespace rayspec {

struct StabilityOptions {
  RunOptions run;  // the device, cases folder, filter, limits, baseline of the runs (run.out is set
                   // per run)
  std::string out = "rayspec-stability";
  std::vector<std::string> tiers = {"fast", "robust",
                                    "exact"};  // the device runs beside the exact tier
  // Run folders of other devices (a run-only binary's `rayspec run` on a
  // machine that only holds a driver): their device bundles counted too.
  std::vector<std::string> saved_devices;
};

// Exit status: 0 when the report was written and the exact tier shows no
// leak and no double hit; 1 when it shows one (the model must be fixed) or
// a report file could not be written; 2 when nothing ran (no case of the
// filter has a `magnitude` parameter, bad options, no device); 128 + the
// signal when interrupted.
int runStability(const StabilityOptions& opt);

}  // namespace rayspec
