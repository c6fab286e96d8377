#include "report/report_tally.h"

#include <algorithm>

#include "case/case.h"

namespace rayspec {

std::string familyLabel(const std::string& case_name) {
  const std::string family = caseFamily(case_name);
  return family.empty() ? "(none)" : family;
}

std::vector<std::string> findingRules(const Finding& finding) {
  std::vector<std::string> rules;
  for (size_t at = 0; at <= finding.rule.size();) {
    const size_t slash = std::min(finding.rule.find('/', at), finding.rule.size());
    if (slash > at) rules.push_back(finding.rule.substr(at, slash - at));
    at = slash + 1;
  }
  return rules;
}

namespace {

bool namedBy(const Finding& f, const std::string& rule) {
  const std::vector<std::string> named = findingRules(f);
  return std::find(named.begin(), named.end(), rule) != named.end();
}

}  // namespace

std::vector<std::string> caseRules(const CaseOutcome& outcome) {
  std::vector<std::string> rules;
  const auto add = [&rules](const std::string& r) {
    if (std::find(rules.begin(), rules.end(), r) == rules.end()) rules.push_back(r);
  };
  for (const std::string& r : outcome.rules) add(r);
  for (const Finding& f : outcome.verdict.findings)
    if (f.status != Status::Pass)
      for (const std::string& r : findingRules(f)) add(r);
  return rules;
}

std::map<std::string, StatusTally> tallyByFamily(const std::vector<CaseOutcome>& outcomes) {
  std::map<std::string, StatusTally> tally;
  for (const CaseOutcome& o : outcomes) {
    StatusTally& t = tally[familyLabel(o.name)];
    ++t.by_status[o.status];
    ++t.cases;
  }
  return tally;
}

std::map<std::string, StatusTally> tallyByRule(const std::vector<CaseOutcome>& outcomes) {
  std::map<std::string, StatusTally> tally;
  for (const CaseOutcome& o : outcomes)
    for (const std::string& rule : caseRules(o)) {
      StatusTally& t = tally[rule];
      ++t.by_status[o.status];
      ++t.cases;
      for (const Finding& f : o.verdict.findings)
        if (f.status != Status::Pass && namedBy(f, rule)) {
          ++t.failing_findings;
          break;
        }
    }
  return tally;
}

}  // namespace rayspec
