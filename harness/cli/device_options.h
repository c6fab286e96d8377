// The device-side options that `rayspec run` shares with the commands that
// run cases the way it does (fuzz, reduce, prove, the studies): one
// declaration and one help text each.
#pragma once

#include <CLI/CLI.hpp>

#include "run/run_options.h"

namespace rayspec {

// --device NAME and --icd FILE...: which Vulkan device runs the cases.
void addDeviceChoice(CLI::App* command, RunOptions& run);

// --no-validation and --strict-validation: the Khronos validation layer.
void addValidationOptions(CLI::App* command, RunOptions& run);

}  // namespace rayspec
