// report.html: one self-contained page (inline style and script, no network
// fetch), images referenced relative to the run folder. At the top the counts
// by family and by rule and a filter; then the failing cases, each folded to
// its findings; then every other case as one row, so the page grows with the
// failures and only a row per passing case.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "base/visible_text.h"
#include "base/whole_file.h"
#include "report/baseline_gate.h"
#include "report/escape.h"
#include "report/report_case_html.h"
#include "report/report_page_assets.h"
#include "report/report_tally.h"
#include "report/write_reports.h"

namespace rayspec {
namespace {

// The groups of the page: the device's failures first, then the cases at fault
// themselves (CaseError), then the rest.
bool failing(const CaseOutcome& o) {
  return o.status != Status::Pass && o.status != Status::NotSupported &&
         o.status != Status::CaseError;
}

// A filter value as the page's script reads it back (decodeURIComponent):
// the text as xmlEscape writes it in the options and the cases' attributes,
// which is ASCII (base/visible_text.h), so what is decoded is what they hold.
std::string urlComponent(const std::string& text) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : visibleText(text)) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

// A count that links to the filter showing those cases ("" when 0).
void countCell(std::ostream& out, int n, const std::string& filter) {
  if (!n) {
    out << "<td></td>";
    return;
  }
  out << "<td class=\"n\"><a href=\"#filter?" << xmlEscape(filter) << "\">" << n << "</a></td>";
}

void statusHeads(std::ostream& out, const std::vector<Status>& statuses) {
  for (Status s : statuses)
    out << "<th class=\"" << statusName(s) << "\">" << statusName(s) << "</th>";
}

void statusCounts(std::ostream& out, const StatusTally& t, const std::string& filter,
                  const std::vector<Status>& statuses) {
  countCell(out, t.cases, filter);
  for (Status s : statuses) {
    const auto it = t.by_status.find(s);
    countCell(out, it == t.by_status.end() ? 0 : it->second,
              (filter.empty() ? "" : filter + "&") + "status=" + statusName(s));
  }
}

void familyTable(std::ostream& out, const std::vector<CaseOutcome>& outcomes,
                 const std::vector<Status>& statuses) {
  out << "<h3>By family</h3>\n<table id=\"by-family\"><tr><th>family</th><th>cases</th>";
  statusHeads(out, statuses);
  out << "</tr>\n";
  for (const auto& [family, tally] : tallyByFamily(outcomes)) {
    out << "<tr><td>" << xmlEscape(family) << "</td>";
    statusCounts(out, tally, "family=" + urlComponent(family), statuses);
    out << "</tr>\n";
  }
  out << "</table>\n";
}

// Every rule of the catalog (the uncovered ones marked), and any other rule a
// case claims or a finding names.
void ruleTable(std::ostream& out, const std::vector<CaseOutcome>& outcomes, const RunInfo& info,
               const std::vector<Status>& statuses) {
  std::map<std::string, StatusTally> tally = tallyByRule(outcomes);
  std::set<std::string> rules;
  for (const auto& [rule, t] : tally) rules.insert(rule);
  for (const auto& [rule, cases] : info.coverage) rules.insert(rule);
  size_t broken = 0, uncovered = 0;
  for (const auto& [rule, t] : tally) broken += t.failing_findings > 0;
  for (const auto& [rule, cases] : info.coverage) uncovered += cases.empty();
  // Folded: some sixty rows would push the filter and the failures down.
  out << "<details id=\"by-rule\"><summary>By rule: " << rules.size() << " rules, " << broken
      << " broken by a finding, " << uncovered << " uncovered</summary>\n"
      << "<p>A case counts under every rule it claims or its failing findings name; "
         "<i>broken</i>: cases with a finding of the rule itself that is not Pass.</p>\n"
      << "<table><tr><th>rule</th><th>title</th><th>claimed by</th><th>ran</th>";
  statusHeads(out, statuses);
  out << "<th>broken</th></tr>\n";
  for (const std::string& rule : rules) {
    std::string title = "(not in the catalog)";
    for (const Rule& r : info.catalog)
      if (r.label == rule) title = r.title;
    const auto claimed = info.coverage.find(rule);
    const size_t claims = claimed == info.coverage.end() ? 0 : claimed->second.size();
    const bool uncovered = claimed != info.coverage.end() && claimed->second.empty();
    out << "<tr><td" << (uncovered ? " class=\"uncovered\"" : "") << ">" << xmlEscape(rule)
        << "</td><td>" << xmlEscape(title) << "</td><td class=\"n\">"
        << (uncovered ? "uncovered" : std::to_string(claims)) << "</td>";
    const StatusTally& t = tally[rule];
    const std::string filter = "rule=" + urlComponent(rule);
    statusCounts(out, t, filter, statuses);
    countCell(out, t.failing_findings, filter);
    out << "</tr>\n";
  }
  out << "</table></details>\n";
}

void filterSelect(std::ostream& out, const char* id, const char* label,
                  const std::set<std::string>& values) {
  out << "<label>" << label << " <select id=\"" << id << "\"><option value=\"\">any</option>";
  for (const std::string& v : values)
    out << "<option value=\"" << xmlEscape(v) << "\">" << xmlEscape(v) << "</option>";
  out << "</select></label> ";
}

void filterBar(std::ostream& out, const std::vector<CaseOutcome>& outcomes,
               const std::vector<Status>& statuses) {
  std::set<std::string> status_names, families, rules;
  for (Status s : statuses) status_names.insert(statusName(s));
  for (const CaseOutcome& o : outcomes) {
    families.insert(familyLabel(o.name));
    for (const std::string& r : caseRules(o)) rules.insert(r);
  }
  out << "<div id=\"filter\">";
  filterSelect(out, "f-status", "status", status_names);
  filterSelect(out, "f-family", "family", families);
  filterSelect(out, "f-rule", "rule", rules);
  out << "<input type=\"search\" id=\"f-search\" placeholder=\"search names, rules, findings\"> "
         "<button id=\"f-clear\">clear</button> <span id=\"shown\"></span></div>\n";
}

void header(std::ostream& out, const std::vector<CaseOutcome>& outcomes, const RunInfo& info) {
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>rayspec "
         "report</title><style>"
      << kReportStyle << "</style><script>" << kReportCheckScript
      << "</script></head><body>\n<h1>rayspec report</h1>\n";
  out << "<p>device: " << xmlEscape(info.device) << " (ICD "
      << xmlEscape(info.icd.empty() ? "unknown" : info.icd) << ") &middot; model: embree "
      << xmlEscape(info.model_tier) << " tier &middot; validation layer "
      << (info.validation ? "on" : "off") << " &middot; " << xmlEscape(info.started) << "</p>\n";
  out << "<p id=\"gate\" class=\""
      << (std::any_of(outcomes.begin(), outcomes.end(), failsRun) ? "Fail" : "Pass") << "\">"
      << xmlEscape(gateLine(outcomes, info.baseline)) << "</p>\n";
  out << "<p id=\"completeness\"" << (info.interrupted ? " class=\"Fail\"" : "") << ">"
      << xmlEscape(runCompleteness(outcomes, info)) << "</p>\n";
  for (const std::string& e : info.teardown_errors)
    out << "<p class=\"Fail\">validation error at device teardown: " << xmlEscape(e) << "</p>\n";
}

// A group's heading: its cases shown by the filter, of how many.
void groupHeading(std::ostream& out, const char* title, size_t cases) {
  out << "<h2>" << title << " (<span class=\"shown\">" << cases << "</span> of " << cases
      << ")</h2>\n";
}

void caseGroups(std::ostream& out, const std::vector<CaseOutcome>& outcomes,
                const std::string& dir) {
  size_t failures = 0, unexpected = 0, errors = 0;
  for (const CaseOutcome& o : outcomes)
    failures += failing(o), unexpected += failing(o) && failsRun(o),
        errors += o.status == Status::CaseError;
  // Those that fail the run first (unexpected ones, under a baseline), then
  // the failures the baseline expects.
  out << "<div class=\"group\">";
  groupHeading(out, "Failing the run", unexpected);
  for (const CaseOutcome& o : outcomes)
    if (failing(o) && failsRun(o)) writeCaseBlock(out, o, dir);
  out << "</div>\n";
  if (failures > unexpected) {
    out << "<div class=\"group\">";
    groupHeading(out, "Failing as the baseline expects", failures - unexpected);
    for (const CaseOutcome& o : outcomes)
      if (failing(o) && !failsRun(o)) writeCaseBlock(out, o, dir);
    out << "</div>\n";
  }
  if (errors) {
    out << "<div class=\"group\">";
    groupHeading(out, "Case errors", errors);
    out << "<p>The case itself is at fault (a malformed file, or undefined behaviour the model "
           "found in it): the device is not blamed.</p>\n";
    for (const CaseOutcome& o : outcomes)
      if (o.status == Status::CaseError) writeCaseBlock(out, o, dir);
    out << "</div>\n";
  }
  out << "<div class=\"group\">";
  groupHeading(out, "Other cases", outcomes.size() - failures - errors);
  out << "<table id=\"others\">";
  writeCaseRowHeader(out);
  for (const CaseOutcome& o : outcomes)
    if (!failing(o) && o.status != Status::CaseError) writeCaseRow(out, o, dir);
  out << "</table></div>\n";
}

}  // namespace

Result<void> writeReportHtml(const std::vector<CaseOutcome>& outcomes, const RunInfo& info,
                             const std::string& path) {
  const std::string dir = std::filesystem::path(path).parent_path().string();
  std::ostringstream out;
  header(out, outcomes, info);
  std::vector<Status> statuses;  // those of the run, in kAllStatuses' order
  for (Status s : kAllStatuses)
    for (const CaseOutcome& o : outcomes)
      if (o.status == s) {
        statuses.push_back(s);
        break;
      }
  out << "<h2>Summary</h2>\n<table id=\"by-status\"><tr><th>cases</th>";
  statusHeads(out, statuses);
  out << "</tr><tr>";
  StatusTally all;
  for (const CaseOutcome& o : outcomes) ++all.by_status[o.status], ++all.cases;
  statusCounts(out, all, "", statuses);
  out << "</tr></table>\n";
  familyTable(out, outcomes, statuses);
  ruleTable(out, outcomes, info, statuses);
  filterBar(out, outcomes, statuses);
  caseGroups(out, outcomes, dir);
  out << "<script>" << kReportScript << "</script>\n</body></html>\n";
  return writeWholeFile(path, out.str());
}

}  // namespace rayspec
