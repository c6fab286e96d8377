// The steps of one case, in the order the run loop (run/run_loop.h) takes them:
//   caseFileError  a file that does not parse (the parser also checks rule
//                  labels against the catalog) is a CaseError (the case is at
//                  fault, not the device)
//   CaseRunner     the model side first (a planted fault chooses its rays by
//                  the model's answer), then the device side, which gets the
//                  model's results; then the judgement. A case the probed
//                  device cannot run (vulkan/case_support.h) is its
//                  NotSupported at once: neither side runs
//   guardCase      an error in any of it is that case's CaseError
//   journalCase    the case joins the run's journal as it ends
//   writeRunReports  the reports in full (now and then, and at the end); a
//                  case whose details break them is a CaseError and the
//                  reports still appear
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "library/case_discovery.h"
#include "parse/parse_case.h"
#include "report/baseline.h"
#include "report/case_outcome.h"
#include "report/run_summary.h"
#include "report/write_reports.h"
#include "run/backend.h"
#include "run/device_probe.h"
#include "run/isolation.h"
#include "run/run_options.h"

namespace rayspec {

// A CaseError outcome: finding `rule` ("case-file", "harness") with the message.
CaseOutcome caseErrorOutcome(const std::string& name, const std::vector<std::string>& rules,
                             const std::string& rule, const std::string& message);

// The CaseError of a case file that did not parse; none when it is usable.
std::optional<CaseOutcome> caseFileError(const CaseFile& file, const ParseResult& parsed);

// step(), or the CaseError naming the error it returned (or the exception of
// the standard library that escaped it).
CaseOutcome guardCase(const std::string& name, const std::vector<std::string>& rules,
                      const std::function<Result<CaseOutcome>()>& step);

// A case's outcome from what its sides gave (nullptr: that side did not
// run): judged, device against model; the model's crash or hang (nothing to
// judge the device by); a device's NotSupported without a model as with one;
// or one side's own status, validation errors included (never a pass:
// nothing was compared). `dir`: where the difference
// images go ("" none). Shared by the run and by a saved run judged anew
// (run/saved_case.h).
CaseOutcome judgeSides(const Case& c, const Plan& plan, const Results* device, const Results* model,
                       const std::string& dir);

// The sides of any case made where they run (a worker process, run/isolation.h).
SideFor modelSideFor(const RunOptions& opt);
SideFor deviceSideFor(const RunOptions& opt);

// A case run by long-lived workers: its index in the cases they were given,
// and the workers of each side (nullptr: that side runs in a process of its
// own for this case).
struct CaseSlot {
  size_t index = 0;
  SideWorker* model = nullptr;
  SideWorker* device = nullptr;
};

class CaseRunner {
 public:
  // device, model: backends that live across cases (--no-isolation); nullptr
  // runs that side of every case in its own child process. With
  // --device-results and --no-isolation the runner reads the saved bundles
  // in this process itself.
  // probed: the live device as its side will see it (run/device_probe.h);
  // none: the device side decides every case itself.
  CaseRunner(const RunOptions& options, Backend* device, Backend* model,
             std::optional<ProbedDevice> probed = std::nullopt);
  // Runs the case on the sides asked for and judges it; or the Harness error.
  // *interrupted: a signal stopped a side; the outcome means nothing then.
  // The bundles go to <out>/<case name><subfolder> (a re-run: "/rerun").
  // With a slot, the sides run in its workers.
  Result<CaseOutcome> run(const Case& c, bool* interrupted, const std::string& subfolder = "",
                          const CaseSlot* slot = nullptr) const;

 private:
  Result<SideResult> runSide(const std::function<Side()>& side, Backend* in_process,
                             SideWorker* worker, const CaseSlot* slot, const Case& c,
                             const Plan& plan, const std::string& dir) const;
  // The device side's NotSupported results of a case it cannot run, decided
  // here and its bundle written where that side writes it; none when the
  // side must run (a planted fault in the case: it may change the answer).
  Result<std::optional<Results>> refusedHere(const Case& c, const Plan& plan,
                                             const std::string& dir) const;
  const RunOptions& opt_;
  Backend* device_;
  Backend* model_;
  std::optional<ProbedDevice> probed_;
  std::unique_ptr<Backend> saved_device_;  // --device-results in this process
};

// Writes the reports of a run folder; the run loop's is writeReports. The
// error: ErrorKind::Input when some case's details are what the reports
// cannot hold, any other kind when they cannot be written at all.
using ReportWriter = std::function<Result<void>(const std::vector<CaseOutcome>&, const RunInfo&,
                                                const std::string& dir)>;

// A case that ended joins the run's journal (report/case_journal.h), and
// its cost.json its bundles; when its details cannot be written (an
// ErrorKind::Input error), the case becomes a CaseError (judged by the
// baseline anew). A file not written is said on stderr.
void journalCase(CaseOutcome& outcome, const Baseline& baseline, const std::string& dir);

// The reports of every case so far (report/write_reports.h); when a case's
// details break them, that case becomes a CaseError (judged by the baseline
// anew) and the reports are written without them. The error: the reports
// not written (ErrorKind::Harness, or what `write` returned).
Result<void> writeRunReports(std::vector<CaseOutcome>& outcomes, const Baseline& baseline,
                             const RunInfo& info, const std::string& dir,
                             const ReportWriter& write = writeReports);

}  // namespace rayspec
