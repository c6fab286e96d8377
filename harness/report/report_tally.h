// The counts at the top of report.html: cases by status per family (the
// case's folder under cases/) and per rule (the rules a case claims or its
// failing findings name), the same grouping the page's filter uses, so a count and
// the rows its filter shows always agree.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "report/case_outcome.h"

namespace rayspec {

struct StatusTally {
  std::map<Status, int> by_status;
  int cases = 0;
  // By rule only: cases with a finding of this rule that is not Pass, the
  // rule itself broken, not a case that failed for another of its rules.
  int failing_findings = 0;
};

// The family a case is counted and filtered under: caseFamily (case/case.h),
// "anyhit" of "anyhit/ignore-keeps-tmax"; "(none)" for a name of one part.
std::string familyLabel(const std::string& case_name);
// The rules a finding names: its rule field split at '/' ("R-IGNORE/R-ISECT-REPORT").
std::vector<std::string> findingRules(const Finding& finding);
// The rules a case claims, then those only its findings that are not Pass
// name, each once. Pass findings are notes, some under labels that are not
// rules ("planted-fault").
std::vector<std::string> caseRules(const CaseOutcome& outcome);

std::map<std::string, StatusTally> tallyByFamily(const std::vector<CaseOutcome>& outcomes);
std::map<std::string, StatusTally> tallyByRule(const std::vector<CaseOutcome>& outcomes);

}  // namespace rayspec
