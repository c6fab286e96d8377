#include "report/report_case_html.h"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "report/baseline_gate.h"
#include "report/escape.h"
#include "report/report_tally.h"

namespace rayspec {
namespace {

bool fileThere(const std::string& path) {
  std::error_code ec;  // a name the file system refuses (too long) is an image that is not there
  return std::filesystem::exists(path, ec);
}

// The opening tag of a case's element: what the filter matches on.
void caseTag(std::ostream& out, const char* tag, const char* cls, const CaseOutcome& o) {
  out << '<' << tag << cls << " id=\"" << xmlEscape(o.name) << "\" data-s=\""
      << statusName(o.status) << "\" data-f=\"" << xmlEscape(familyLabel(o.name)) << "\">";
}

// The words of the ".r" element.
void ruleWords(std::ostream& out, const CaseOutcome& o) {
  const char* space = "";
  for (const std::string& r : caseRules(o)) out << space << xmlEscape(r), space = " ";
}

std::string baselineText(const CaseOutcome& o) {
  if (o.baseline == BaselineMatch::None) return std::string();
  return std::string(" (") + gateWord(o.baseline) + ": " + xmlEscape(o.baseline_note) + ")";
}

// Rays whose behaviour is undefined (R-UB), apart from the findings: never judged.
void undefinedTable(std::ostream& out, const CaseOutcome& o) {
  out << "<table class=\"undefined\"><tr><th colspan=\"4\">rays with undefined behaviour (R-UB): "
         "not judged</th></tr>"
      << "<tr><th>reason</th><th>rays</th><th>first rays</th><th>first ray's cause</th></tr>\n";
  for (const UndefinedRays& u : o.verdict.undefined) {
    out << "<tr><td>" << undefinedReasonName(u.reason) << "</td><td>" << u.ray_count << "</td><td>";
    for (uint32_t r : u.rays) out << r << ' ';
    out << "</td><td>" << xmlEscape(u.what) << "</td></tr>\n";
  }
  out << "</table>\n";
}

void findingsTable(std::ostream& out, const CaseOutcome& o) {
  if (o.verdict.findings.empty()) return;
  out << "<table><tr><th>status</th><th>rule</th><th>finding</th><th>rays</th></tr>\n";
  for (const Finding& f : o.verdict.findings) {
    out << "<tr><td class=\"" << statusName(f.status) << "\">" << statusName(f.status)
        << "</td><td>" << xmlEscape(f.rule) << "</td><td>" << xmlEscape(f.message) << "</td><td>";
    if (f.ray_count) out << f.ray_count << " (first:";
    for (uint32_t r : f.rays) out << ' ' << r;
    if (f.ray_count) out << ')';
    out << "</td></tr>\n";
  }
  out << "</table>\n";
}

void imageFigure(std::ostream& out, const std::string& dir, const std::string& rel,
                 const char* label) {
  if (!fileThere(dir + "/" + rel)) return;
  out << "<figure><img src=\"" << xmlEscape(rel) << "\" alt=\"" << label << "\"><figcaption>"
      << label << "</figcaption></figure>";
}

// A row per field of each ray, under a row naming the ray; the fields where
// device and model agree are of class "same", hidden until "every field" is
// ticked, their one value spanning both columns.
void rayTable(std::ostream& out, const std::vector<RayRow>& rows) {
  out << "<label><input type=\"checkbox\" class=\"allf\"> every field</label>\n"
      << "<table class=\"rays\"><tr><th>field</th><th>device</th><th>model</th></tr>\n";
  for (size_t i = 0; i < rows.size(); ++i) {
    const RayRow& r = rows[i];
    if (i == 0 || rows[i - 1].ray != r.ray)
      out << "<tr class=\"ray\"><th colspan=\"3\">ray " << r.ray << " (x " << r.x << ", y " << r.y
          << ")</th></tr>\n";
    if (r.device == r.model)
      out << "<tr class=\"same\"><td>" << xmlEscape(r.field) << "</td><td colspan=\"2\">"
          << xmlEscape(r.device) << "</td></tr>\n";
    else
      out << "<tr><td>" << xmlEscape(r.field) << "</td><td>" << xmlEscape(r.device) << "</td><td>"
          << xmlEscape(r.model) << "</td></tr>\n";
  }
  out << "</table>\n";
}

// What the <details> of a failing case holds, in words for its summary.
std::string detailsSummary(const CaseOutcome& o, size_t figures) {
  std::string text;
  const auto part = [&text](const std::string& p) {
    text += (text.empty() ? "" : ", ") + p;
  };
  if (figures) part(std::to_string(figures) + " images");
  if (!o.verdict.undefined.empty()) part("undefined rays (R-UB)");
  if (!o.failing_rays.empty()) {
    size_t rays = 0, differing = 0;
    for (size_t i = 0; i < o.failing_rays.size(); ++i) {
      rays += i == 0 || o.failing_rays[i - 1].ray != o.failing_rays[i].ray;
      differing += o.failing_rays[i].device != o.failing_rays[i].model;
    }
    part("per-ray table: " + std::to_string(rays) + " rays, " + std::to_string(differing) +
         " differing fields of " + std::to_string(o.failing_rays.size()));
  }
  return text;
}

}  // namespace

void writeCaseBlock(std::ostream& out, const CaseOutcome& o, const std::string& dir) {
  caseTag(out, "div", " class=\"case\"", o);
  out << "<h3>" << xmlEscape(o.name) << " <span class=\"" << statusName(o.status) << "\">"
      << statusName(o.status) << "</span>" << baselineText(o) << "</h3>\n";
  out << "<p>" << xmlEscape(o.headline) << "</p><p>rules: <span class=\"r\">";
  ruleWords(out, o);
  out << "</span> &middot; device " << o.device_seconds << " s, model " << o.model_seconds
      << " s</p>\n";
  findingsTable(out, o);
  size_t figures = 0;
  for (const std::string& im : o.images)
    for (const char* side : {"/device/", "/model/", "/diff/"})
      figures += fileThere(dir + "/" + o.name + side + im + ".png");
  const std::string summary = detailsSummary(o, figures);
  if (!summary.empty()) {
    out << "<details><summary>" << summary << "</summary>\n";
    for (const std::string& im : o.images) {
      out << "<div class=\"images\">";
      imageFigure(out, dir, o.name + "/device/" + im + ".png", "device");
      imageFigure(out, dir, o.name + "/model/" + im + ".png", "model");
      imageFigure(out, dir, o.name + "/diff/" + im + ".png", "difference");
      out << "</div>\n";
    }
    if (!o.verdict.undefined.empty()) undefinedTable(out, o);
    if (!o.failing_rays.empty()) rayTable(out, o.failing_rays);
    out << "</details>\n";
  }
  out << "</div>\n";
}

void writeCaseRowHeader(std::ostream& out) {
  out << "<tr><th>case</th><th>status</th><th>rules</th><th>s</th><th>note</th></tr>\n";
}

// Short: a run has a row per passing case.
void writeCaseRow(std::ostream& out, const CaseOutcome& o, const std::string& dir) {
  caseTag(out, "tr", "", o);
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.2f", o.seconds);
  out << "<td>" << xmlEscape(o.name) << "</td><td class=\"" << statusName(o.status) << "\">"
      << statusName(o.status) << "</td><td class=\"r\">";
  ruleWords(out, o);
  out << "</td><td>" << seconds << "</td>";
  std::ostringstream note;  // left out when empty: most rows have none
  for (const std::string& im : o.images) {
    const std::string rel = o.name + "/device/" + im + ".png";
    if (fileThere(dir + "/" + rel))
      note << "<a href=\"" << xmlEscape(rel) << "\">" << xmlEscape(im) << "</a> ";
  }
  note << (o.status == Status::Pass ? std::string() : xmlEscape(o.headline)) << baselineText(o);
  if (!o.verdict.undefined.empty()) {
    note << "<details><summary>undefined rays (R-UB)</summary>\n";
    undefinedTable(note, o);
    note << "</details>";
  }
  if (!note.str().empty()) out << "<td>" << note.str() << "</td>";
  out << "</tr>\n";
}

}  // namespace rayspec
