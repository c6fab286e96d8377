#include "run/run_only.h"

#include <cstdio>

#include "model/model_engine.h"

namespace rayspec {

RunOptions optionsForThisBuild(const RunOptions& requested) {
  if (modelInThisBuild()) return requested;
  RunOptions opt = requested;
  opt.no_model = true;
  std::printf(
      "run-only build: no model; judge these results where the full build is, with rayspec run "
      "--device-results %s\n",
      opt.out.c_str());
  return opt;
}

}  // namespace rayspec
