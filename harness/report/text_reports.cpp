// results.csv, junit.xml, summary.json and summary.txt.
#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "base/visible_text.h"
#include "base/whole_file.h"
#include "report/baseline_gate.h"
#include "report/case_cost.h"
#include "report/escape.h"
#include "report/json_text.h"
#include "report/outcome_json.h"
#include "report/write_reports.h"

namespace rayspec {

const char* deqpStatusName(Status s) {
#define RAYSPEC_DEQP_NAME(id, name, deqp) deqp,
  static constexpr const char* kDeqpNames[] = {RAYSPEC_STATUSES(RAYSPEC_DEQP_NAME)};
#undef RAYSPEC_DEQP_NAME
  return kDeqpNames[static_cast<size_t>(s)];
}

Result<void> writeResultsCsv(const std::vector<CaseOutcome>& outcomes, const std::string& path) {
  std::ostringstream out;
  for (const CaseOutcome& o : outcomes)
    out << csvField(visibleLine(o.name)) << ',' << deqpResultName(o) << ',' << o.seconds << '\n';
  return writeWholeFile(path, out.str());
}

Result<void> writeJunitXml(const std::vector<CaseOutcome>& outcomes, const std::string& path) {
  int failures = 0, skipped = 0, errors = 0;
  double total = 0;
  for (const CaseOutcome& o : outcomes) {
    failures += o.status == Status::Fail || o.status == Status::QualityWarning ||
                o.status == Status::CaseError;
    errors += o.status == Status::Crash || o.status == Status::Timeout;
    skipped += o.status == Status::NotSupported;
    total += o.seconds;
  }
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << "<testsuites><testsuite name=\"rayspec\" tests=\"" << outcomes.size() << "\" failures=\""
      << failures << "\" errors=\"" << errors << "\" skipped=\"" << skipped << "\" time=\"" << total
      << "\">\n";
  for (const CaseOutcome& o : outcomes) {
    const std::string family = o.name.substr(0, o.name.find('/'));
    out << "  <testcase classname=\"rayspec." << xmlEscape(family) << "\" name=\""
        << xmlEscape(o.name) << "\" time=\"" << o.seconds << "\">";
    switch (o.status) {
      case Status::Pass:
        break;
      case Status::NotSupported:
        out << "<skipped message=\"" << xmlEscape(o.headline) << "\"/>";
        break;
      case Status::Crash:
      case Status::Timeout:
        out << "<error type=\"" << statusName(o.status) << "\" message=\"" << xmlEscape(o.headline)
            << "\"/>";
        break;
      default:
        out << "<failure type=\"" << statusName(o.status) << "\" message=\""
            << xmlEscape(o.headline) << "\"/>";
    }
    out << "</testcase>\n";
  }
  out << "</testsuite></testsuites>\n";
  return writeWholeFile(path, out.str());
}

Result<void> writeSummaryJson(const std::vector<CaseOutcome>& outcomes, const RunInfo& info,
                              const std::string& path) {
  nlohmann::json j;
  j["device"] = info.device;
  j["icd"] = info.icd;
  j["variant"] = info.variant;
  j["model_tier"] = info.model_tier;
  j["started"] = info.started;
  j["baseline"] = info.baseline;
  j["validation"] = info.validation;
  j["teardown_validation_errors"] = info.teardown_errors;
  j["planned_cases"] = std::max(info.planned_cases, outcomes.size());
  j["interrupted"] = info.interrupted;
  std::map<std::string, int> counts;
  for (Status s : kAllStatuses) counts[statusName(s)] = 0;
  j["cases"] = nlohmann::json::array();
  std::vector<std::string> case_errors, failing;
  for (const CaseOutcome& o : outcomes) {
    ++counts[statusName(o.status)];
    if (o.status == Status::CaseError) case_errors.push_back(o.name);
    if (failsRun(o)) failing.push_back(o.name);
    j["cases"].push_back(outcomeJson(o));
  }
  j["fails_run"] = failing;  // the cases that make the run fail (baseline applied)
  j["counts"] = counts;
  j["case_errors"] = case_errors;     // cases at fault themselves, not the device
  j["cost"] = runCostJson(outcomes);  // where the run's time went (report/case_cost.h)
  RAYSPEC_TRY(const std::string text, jsonText(j, 1));
  return writeWholeFile(path, text + '\n');
}

std::string runCompleteness(const std::vector<CaseOutcome>& outcomes, const RunInfo& info) {
  const size_t planned = std::max(info.planned_cases, outcomes.size());
  if (info.interrupted)
    return "INTERRUPTED: " + std::to_string(outcomes.size()) + " of " + std::to_string(planned) +
           " planned cases ran";
  return "complete: " + std::to_string(outcomes.size()) + " of " + std::to_string(planned) +
         " cases";
}

namespace {

// Text from input (a case file's name, a saved run, the device's words) made
// visible, each field on its line.
void caseText(std::ostream& out, const CaseOutcome& o) {
  out << visibleLine(o.name) << ": " << visibleLine(o.headline);
  if (o.baseline != BaselineMatch::None) out << "  [" << gateWord(o.baseline) << "]";
  out << '\n';
  for (const Finding& f : o.verdict.findings)
    out << "    [" << statusName(f.status) << "] " << visibleLine(f.rule) << ": "
        << visibleLine(f.message) << '\n';
  for (const UndefinedRays& u : o.verdict.undefined) {
    out << "    undefined (R-UB, not judged): " << undefinedReasonName(u.reason) << ", "
        << u.ray_count << " rays; first:";
    for (uint32_t r : u.rays) out << ' ' << r;
    out << "; " << visibleLine(u.what) << '\n';
  }
}

}  // namespace

Result<void> writeSummaryText(const std::vector<CaseOutcome>& outcomes, const RunInfo& info,
                              const std::string& path) {
  std::ostringstream out;
  out << runCompleteness(outcomes, info) << '\n' << gateLine(outcomes, info.baseline) << '\n';
  // The results that fail the run first, then every other; the cases at fault apart.
  const auto group = [&](const char* title, auto in_group) {
    bool header = false;
    for (const CaseOutcome& o : outcomes) {
      if (!in_group(o)) continue;
      if (!header) out << '\n' << title << '\n';
      header = true;
      caseText(out, o);
    }
  };
  group("Failing the run:",
        [](const CaseOutcome& o) { return o.status != Status::CaseError && failsRun(o); });
  group("Other cases:",
        [](const CaseOutcome& o) { return o.status != Status::CaseError && !failsRun(o); });
  group("Case errors (the case itself is at fault, not the device):",
        [](const CaseOutcome& o) { return o.status == Status::CaseError; });
  out << '\n' << runCostText(outcomes);
  return writeWholeFile(path, out.str());
}

Result<void> writeReports(const std::vector<CaseOutcome>& outcomes, const RunInfo& info,
                          const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return errorOf(ErrorKind::Harness, "cannot create " + dir + ": " + ec.message());
  std::optional<Error> first;
  std::string others;  // the other reports not written
  for (const Result<void>& written :
       {writeResultsCsv(outcomes, dir + "/" + kResultsCsvFile),
        writeJunitXml(outcomes, dir + "/" + kJunitXmlFile),
        writeSummaryJson(outcomes, info, dir + "/" + kSummaryJsonFile),
        writeSummaryText(outcomes, info, dir + "/" + kSummaryTextFile),
        writeFailuresCsv(outcomes, info.baseline, dir + "/" + kFailuresCsvFile),
        writeReportHtml(outcomes, info, dir + "/" + kReportHtmlFile)}) {
    if (written) continue;
    if (!first)
      first = written.error();
    else
      others += "; " + written.error().format();
  }
  if (!first) return {};
  first->message += others;
  return *first;
}

}  // namespace rayspec
