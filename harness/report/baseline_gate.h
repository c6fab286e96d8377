// The regression gate: each case's result against the driver's baseline
// (report/baseline.h), the way deqp-runner judges them.
//   expected       the result the baseline lists, or Pass for a case it does
//                  not list: does not fail the run
//   unexpected     a failing status (Fail, Crash, Timeout, CaseError) other
//                  than the expected one: fails the run, after one re-run;
//                  when the re-run gives another result it is a Flake, which
//                  does not fail the run but is reported for the flakes file
//   unexpected pass  the baseline lists a failure and the case no longer
//                  fails: fails the run until the baseline is updated
//   known flake    an unexpected result of a case the flakes file names:
//                  does not fail the run
//   skipped        named by the skips file: never run, NotSupported
// A result that is neither failing nor expected to fail (a NotSupported or
// QualityWarning where Pass was expected) is judged by its status alone.
#pragma once

#include <string>
#include <vector>

#include "report/baseline.h"
#include "report/case_outcome.h"

namespace rayspec {

// The result the baseline expects of a case: its entry, or Pass.
Status expectedStatus(const Baseline& baseline, const std::string& name);

// Sets outcome.baseline and baseline_note. Returns true when the outcome is
// an unexpected failure that a baseline run re-runs once (applyRerun).
bool applyBaseline(const Baseline& baseline, CaseOutcome& outcome);

// After the re-run of an unexpected failure: a Flake when the re-run's
// status differs, otherwise it stays an unexpected failure.
void applyRerun(CaseOutcome& outcome, const CaseOutcome& rerun);

// The outcome of a case the skips file names.
CaseOutcome skippedOutcome(const std::string& name, const NamePattern& pattern);

// Whether this outcome fails the run.
bool failsRun(const CaseOutcome& outcome);

// The results the baseline did not expect (those that fail the run, and the
// flakes), as a baseline-form CSV: `case,Status` with a comment saying what
// was expected. Written as failures.csv into a run folder.
// baseline_file: the baseline the run was judged by ("" none). The error:
// ErrorKind::Harness, the file not written.
Result<void> writeFailuresCsv(const std::vector<CaseOutcome>& outcomes,
                              const std::string& baseline_file, const std::string& path);

// The gate in one line, for the top of summary.txt and report.html and the
// console: the baseline judged by ("none: every failing status fails the
// run" when ""), PASS or FAIL with the results that fail the run (unexpected
// failures and unexpected passes apart), the expected failures and the
// flakes. Starts "Gate: ".
std::string gateLine(const std::vector<CaseOutcome>& outcomes, const std::string& baseline_file);

// A few words for the console and the reports: "expected", "known flake", ...
const char* gateWord(BaselineMatch m);

// deqp-runner's name for a result: the status, or ExpectedFail, Flake, ...
const char* deqpResultName(const CaseOutcome& outcome);

}  // namespace rayspec
