// The one place planted faults (test only: `rayspec run --plant-fault NAME`,
// harness/fault/) enter a run. The run's own steps (run/case_steps.h) know
// only the three questions below; the hooks they arm are the model's
// (model/model_faults.h, set by fault/'s case mutations) and the Vulkan
// side's (vulkan/vk_fault_hook.h). docs/layout-and-conventions.md, "The fault
// seam", lists them all, and ctest style/fault-seam fails when product code
// outside them names one.
#pragma once

#include <memory>
#include <string>

#include "base/result.h"
#include "results/results.h"
#include "run/isolation.h"
#include "run/run_options.h"
#include "vulkan/vk_fault_hook.h"

namespace rayspec {

// What stops the fault asked for from being planted in this run: a name that
// is no fault, a process fault without child processes, a fault made from
// the model's results in a run-only build, a Vulkan error fault on saved
// results; an ErrorKind::Input error saying which.
Result<void> plantedFaultError(const RunOptions& opt);

// The names `--plant-fault` takes, comma-separated, for the message of an
// unknown one (`rayspec faults` describes each).
std::string plantableFaultNames();

// The fault planted in this case ("" none).
std::string plantedFaultIn(const RunOptions& opt, const std::string& case_name);

// True when the fault picks its rays by the model's results of the case, so
// the device side needs them before it runs.
bool faultReadsModel(const std::string& fault);

// The layout fault a standalone C reproducer of a case (export/export_c.h)
// is given for the planted fault `fault`: None for none; the fault itself
// where the builds' input layout obeys it (stride-ignored, offsets-ignored,
// vertex-format-misread: vulkan/build_layout.h), so the file's builds misread
// as the run's did; else an Input error saying why a C file cannot carry it
// (the fault is made in rayspec's results or in a step the file does not take).
Result<LayoutFault> exportedLayoutFault(const std::string& fault);

// Arms the device side with the fault: a Vulkan call made to fail (`before`,
// cleared in `after`), a crash or hang in the device's process, or the
// device's results replaced by what a device breaking one rule gives (chosen
// by `model`, the model's results of the case). `after` returns the note
// the case's report shows. No fault: `s` unchanged.
void armDeviceSide(Side& s, const std::string& fault, std::shared_ptr<const Results> model,
                   const std::string& run_dir);

}  // namespace rayspec
