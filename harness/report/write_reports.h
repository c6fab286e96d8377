// The reports of a run, written into its output folder:
//   results.csv   deqp-runner's CSV (case,Status,duration; no header) with
//                 deqp-runner status names (Pass, Fail, Warn, Skip, Crash, Timeout)
//   junit.xml     one testcase per case (failure / skipped elements)
//   summary.json  counts per status, every case's status, headline, findings and
//                 undefined rays (R-UB, never judged), the CaseError cases by name,
//                 planned_cases and interrupted
//   summary.txt   a line saying whether the run is complete, then the same for
//                 people, one block per case, CaseError cases apart
//   failures.csv  the results the baseline did not expect, in baseline form
//                 (report/baseline_gate.h); every failure when there is none
//   report.html   whether the run is complete, counts by status per family and
//                 per rule (rule coverage with them), a filter (status, family,
//                 rule, text); failing cases first, then the case errors (the case
//                 at fault, not the device), each with its findings and, folded,
//                 device / model / difference images side by side, undefined rays
//                 apart and per-ray tables of failing rays (the differing fields
//                 shown); a row per other case (report/report_case_html.h)
#pragma once

#include <array>

#include <map>
#include <string>
#include <vector>

#include "base/result.h"
#include "report/case_outcome.h"
#include "report/rule_catalog.h"

namespace rayspec {

struct RunInfo {
  std::string device, model_tier, started;
  std::string baseline;  // the baseline file the run was judged by ("" none)
  std::string icd;       // the driver manifest the device came from ("" when unknown)
  // What the run did to every case (run/run_options.h runVariant): "" for the
  // cases as written. Runs of another variant never resume, judge or merge
  // into each other.
  std::string variant;
  bool validation = false;
  size_t planned_cases = 0;  // cases the run set out to run (0: as many as it has outcomes)
  // Not every planned case ran: the run is still going, was stopped by a
  // signal, or was killed (a run writes its reports marked interrupted until
  // the last case is done).
  bool interrupted = false;
  std::vector<std::string> teardown_errors;
  std::vector<Rule> catalog;
  std::map<std::string, std::vector<std::string>> coverage;  // rule -> cases
};

// A run variant for people: "as written" or "by through update".
std::string variantText(const std::string& variant);

// deqp-runner's name for a status.
const char* deqpStatusName(Status s);

// Each writer writes its file whole or not at all (base/whole_file.h: a
// full disk leaves the copy that was there as it was). The error:
// ErrorKind::Harness when its file cannot be written ("PATH: cannot write:
// WHY"); the JSON one also ErrorKind::Input when a case's details are text
// JSON cannot hold (report/json_text.h).
Result<void> writeResultsCsv(const std::vector<CaseOutcome>& outcomes, const std::string& path);
Result<void> writeJunitXml(const std::vector<CaseOutcome>& outcomes, const std::string& path);
Result<void> writeSummaryJson(const std::vector<CaseOutcome>& outcomes, const RunInfo& info,
                              const std::string& path);
Result<void> writeSummaryText(const std::vector<CaseOutcome>& outcomes, const RunInfo& info,
                              const std::string& path);
// "complete: 12 of 12 cases" or "INTERRUPTED: 3 of 12 planned cases ran".
std::string runCompleteness(const std::vector<CaseOutcome>& outcomes, const RunInfo& info);
Result<void> writeReportHtml(const std::vector<CaseOutcome>& outcomes, const RunInfo& info,
                             const std::string& path);

// The names of the files above, as writeReports writes them into its folder.
inline constexpr const char* kResultsCsvFile = "results.csv";
inline constexpr const char* kJunitXmlFile = "junit.xml";
inline constexpr const char* kSummaryJsonFile = "summary.json";
inline constexpr const char* kSummaryTextFile = "summary.txt";
inline constexpr const char* kFailuresCsvFile = "failures.csv";
inline constexpr const char* kReportHtmlFile = "report.html";
inline constexpr std::array<const char*, 6> kReportFiles = {kResultsCsvFile,  kJunitXmlFile,
                                                            kSummaryJsonFile, kSummaryTextFile,
                                                            kFailuresCsvFile, kReportHtmlFile};

// All of the above into dir (each written even when one before failed). The
// error: the first, its message followed by those of the other reports not
// written.
Result<void> writeReports(const std::vector<CaseOutcome>& outcomes, const RunInfo& info,
                          const std::string& dir);

}  // namespace rayspec
