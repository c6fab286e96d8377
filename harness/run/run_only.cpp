#include "run/run_only.h"

#include <cstdio>

#include "fault/planted_fault.h"
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

std::string runOnlyError(const RunOptions& opt) {
  if (modelInThisBuild()) return {};
  if (const FaultInfo* f = findFault(opt.plant_fault); f && f->kind != FaultKind::Process)
    return "the fault '" + opt.plant_fault +
           "' is made from the model's results, which this run-only build lacks (crash, hang and "
           "the Vulkan error faults work here; plant it when judging, with --device-results)";
  return {};
}

}  // namespace rayspec
