// A run-only build (RAYSPEC_WITH_MODEL=OFF, preset `device`) has no model:
// `rayspec run` runs the device side of every case and saves its results
// bundles, judging nothing; the full build judges that folder with
// `rayspec run --device-results DIR` (run/device_results.h).
#pragma once

#include <string>

#include "run/run_options.h"

namespace rayspec {

// The options as this build runs them: `requested` in the full build; in a
// run-only build the device side only, with a note on stdout saying so.
RunOptions optionsForThisBuild(const RunOptions& requested);

}  // namespace rayspec
