#include "cli/device_options.h"

#include "cli/commands.h"

namespace rayspec {

void addDeviceChoice(CLI::App* command, RunOptions& run) {
  command->add_option("--device", run.device,
                      "Vulkan device name (substring); default: the first with ray tracing");
  command->add_option("--icd", run.icd_files, kIcdOptionHelp)->delimiter(':');
}

void addValidationOptions(CLI::App* command, RunOptions& run) {
  command->add_flag("--no-validation", run.no_validation,
                    "Do not load the Khronos validation layer");
  command->add_flag("--strict-validation", run.strict_validation,
                    "Fail when the validation layer is not installed (ctest sets this); a "
                    "validation error fails its case either way");
}

}  // namespace rayspec
