// `rayspec check` and the portability check of `rayspec run` (--check-case,
// --no-check-case; run/case_check.h), cli/check_command.cpp.
#pragma once

#include <CLI/CLI.hpp>

#include "cli/subcommands.h"
#include "run/case_check.h"
#include "run/run_options.h"

namespace rayspec {

Subcommand addCheckCommand(CLI::App& app);
// run's --check-case and --no-check-case, into run_opt.check_case.
void addCheckCaseOptions(CLI::App* run, RunOptions& run_opt);
// The check `rayspec run` gives runCases: the case's notPortableText (none
// without the model: --no-model, a run-only build).
CaseCheck portabilityCheckFor(const RunOptions& opt);

}  // namespace rayspec
