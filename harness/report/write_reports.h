// The reports of a run, written into its output folder:
//   results.csv   deqp-runner's CSV (case,Status,duration; no header) with
//                 deqp-runner status names (Pass, Fail, Warn, Skip, Crash, Timeout)
//   junit.xml     one testcase per case (failure / skipped elements)
//   summary.json  counts per status, every case's status, headline, findings and
//                 undefined rays (R-UB, never judged), the CaseError cases by name
//   summary.txt   the same for people, one block per case, CaseError cases apart
//   report.html   failing cases first, then the case errors (the case at fault,
//                 not the device), device / model / difference images side by
//                 side, per-ray tables of failing rays, undefined rays apart,
//                 rule coverage
#pragma once

#include <map>
#include <string>
#include <vector>

#include "report/case_outcome.h"
#include "report/rule_catalog.h"

namespace rayspec {

struct RunInfo {
  std::string device, model_tier, started;
  bool validation = false;
  std::vector<std::string> teardown_errors;
  std::vector<Rule> catalog;
  std::map<std::string, std::vector<std::string>> coverage;  // rule -> cases
};

// deqp-runner's name for a status.
const char* deqpStatusName(Status s);

std::string writeResultsCsv(const std::vector<CaseOutcome>& outcomes, const std::string& path);
std::string writeJunitXml(const std::vector<CaseOutcome>& outcomes, const std::string& path);
std::string writeSummaryJson(const std::vector<CaseOutcome>& outcomes, const RunInfo& info, const std::string& path);
std::string writeSummaryText(const std::vector<CaseOutcome>& outcomes, const std::string& path);
std::string writeReportHtml(const std::vector<CaseOutcome>& outcomes, const RunInfo& info, const std::string& path);

// All of the above into dir; returns the first error.
std::string writeReports(const std::vector<CaseOutcome>& outcomes, const RunInfo& info, const std::string& dir);

}  // namespace rayspec
