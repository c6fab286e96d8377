// One side of a case (the model or the device) run in a child process, or in
// this process with --no-isolation. The same function runs both sides: the
// child makes the backend (Vulkan is never initialised in the parent before a
// fork), runs the case, closes the backend (validation errors at teardown join
// the case's validation messages), calls `after` (planted faults), writes the
// results bundle and exits; the parent reads the bundle back and writes the
// PNG / EXR files (OpenImageIO's and OpenEXR's thread pools belong to the
// parent). A child that crashes, hangs past the timeout or runs out of memory
// gives Results with status Crash or Timeout, and the run goes on.
// Cost on lavapipe with the validation layer: about 0.2 s per device child
// (instance + device creation); a model child costs a few milliseconds.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "run/backend.h"
#include "run/child_process.h"
#include "run/worker.h"

namespace rayspec {

struct Side {
  std::string label;         // "model" or "device": names the process in messages
  std::string backend_name;  // Results::backend when the child left no results ("model", "vulkan")
  BackendFactory make;       // makes the backend where it runs
  // Runs after the backend, where it ran, and may change the results (a
  // planted fault); returns a note for the report ("" none).
  std::function<std::string(const Case&, const Plan&, Results&)> after;
  // Runs just before the backend, where it runs (a planted device error).
  std::function<void()> before;
};

struct SideResult {
  Results results;
  std::string note;  // what `after` said
  bool interrupted =
      false;  // a signal stopped the run while this side ran: the results mean nothing
};

// The functions below that run a side return an ErrorKind::Harness error
// when the case or the harness is at fault, not the backend: the results
// bundle could not be written or read, the child could not report. The run
// loop makes the case a CaseError.

// In a child process under `limits`; the bundle goes to `dir`.
Result<SideResult> runIsolated(const Side& side, const Case& c, const Plan& plan,
                               const ChildLimits& limits, const std::string& dir);

// Makes a case's side where it runs (in the worker process); `dir` is the
// side's bundle folder.
using SideFor = std::function<Result<Side>(const Case& c, const std::string& dir)>;

// One side of many cases in a long-lived worker process (run/worker.h): the
// backend is made at the worker's first case and lives across cases; a case
// that crashes, hangs or runs out of memory ends the worker, is that case's
// Crash or Timeout, and the next case gets a new worker (a new device).
class SideWorker {
 public:
  // `cases`: the run's cases, all of them before the first run() (the worker
  // is a fork of this process and sees them as they were then).
  SideWorker(std::string label, std::string backend_name, const std::vector<Case>& cases,
             SideFor side_for, const ChildLimits& limits);
  // cases[index] on this side; the bundle goes to `dir`.
  Result<SideResult> run(size_t index, const Plan& plan, const std::string& dir);
  // Ends the worker: what its backend reported at teardown (validation errors
  // at device destruction).
  std::vector<std::string> close();
  int processesStarted() const { return worker_.started(); }

 private:
  std::string label_, backend_name_;
  const std::vector<Case>& cases_;
  ChildLimits limits_;
  Worker worker_;
};

// In this process, with a backend that lives across cases (--no-isolation).
Result<SideResult> runInProcess(const Side& side, Backend& backend, const Case& c, const Plan& plan,
                                const std::string& dir);

}  // namespace rayspec
