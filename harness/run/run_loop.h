// `rayspec run`: every case file in turn (run/case_steps.h), the reports
// rewritten after each one, and the exit status.
#pragma once

#include <cstddef>

#include "report/run_summary.h"
#include "run/case_check.h"
#include "run/run_options.h"

namespace rayspec {

// Exit statuses of a run (and of `rayspec compare`).
inline constexpr int kExitPass = 0;
inline constexpr int kExitFailing =
    1;  // a case failed (Fail, Crash, Timeout, CaseError), baseline aside
inline constexpr int kExitSetup =
    2;  // nothing ran: bad options, no such device, no case, bad baseline
inline constexpr int kExitNothingCompared = 3;  // every case was NotSupported: nothing was compared
inline constexpr int kExitReports =
    4;  // the cases ran, but a report could not be written (the message names it and why)
inline constexpr int kExitNotSupported =
    77;  // a single case, NotSupported on a device that exists (ctest's skip)
// Interrupted by SIGINT / SIGTERM: 128 + the signal, reports marked interrupted.

// `check`: what a case must pass before it runs (the command line's
// portability check, run/case_check.h), for the cases checksCase selects;
// none: no case is checked.
int runCases(const RunOptions& opt, const CaseCheck& check = {});

// The exit status of a run that got as far as its cases: `planned` cases,
// `device_found` when the device side had a device, `signal` the one that
// stopped it (0 none).
int runExitStatus(const RunSummary& summary, size_t planned, bool device_found, int signal);

}  // namespace rayspec
