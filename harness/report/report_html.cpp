// report.html: one self-contained page (inline style, one small script),
// images referenced relative to the run folder.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "report/baseline_gate.h"
#include "report/escape.h"
#include "report/write_reports.h"

namespace rayspec {
namespace {

const char* kStyle = R"(body{font-family:sans-serif;margin:1.5em;color:#222}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:2px 6px;font-size:13px}
.Pass{color:#1a7f37}.Fail,.Crash,.Timeout{color:#cf222e;font-weight:bold}.QualityWarning{color:#9a6700}
.CaseError{color:#8250df;font-weight:bold}.undefined{background:#f6f0ff}
.NotSupported{color:#57606a}.case{border:1px solid #ddd;padding:.5em 1em;margin:1em 0}
.images figure{display:inline-block;margin:0 1em 0 0}.images img{image-rendering:pixelated;width:256px;border:1px solid #999}
.uncovered{color:#cf222e}#passing.hidden{display:none})";

// The toggle of passing cases, and a self-check a headless browser can read
// back from the DOM: data-images (loaded), data-broken-images and
// data-script-errors on <body> once the page has loaded.
const char* kCheckScript = R"(window.rayspecErrors=0;window.addEventListener('error',function(e){
if(e.target&&e.target.tagName==='IMG')return;window.rayspecErrors++;
document.body.dataset.scriptErrors=window.rayspecErrors;},true);)";

const char* kScript = R"(document.getElementById('toggle').addEventListener('click',function(){
document.getElementById('passing').classList.toggle('hidden');});
window.addEventListener('load',function(){var ok=0,broken=[];
Array.prototype.forEach.call(document.images,function(i){
if(i.complete&&i.naturalWidth>0)ok++;else broken.push(i.getAttribute('src'));});
var b=document.body.dataset;b.images=ok;b.brokenImages=broken.length;b.brokenList=broken.join(' ');
b.scriptErrors=window.rayspecErrors;b.checked='1';});)";

// The groups of the page: the device's failures first, then the cases at fault
// themselves (CaseError), then the rest.
bool failing(const CaseOutcome& o) {
  return o.status != Status::Pass && o.status != Status::NotSupported &&
         o.status != Status::CaseError;
}

// Rays whose behaviour is undefined (R-UB), apart from the findings: never judged.
void undefinedTable(std::ostream& out, const CaseOutcome& o) {
  if (o.verdict.undefined.empty()) return;
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

void imageFigure(std::ostream& out, const std::string& dir, const std::string& rel,
                 const char* label) {
  std::error_code ec;  // a name the file system refuses (too long) is an image that is not there
  if (!std::filesystem::exists(dir + "/" + rel, ec)) return;
  out << "<figure><img src=\"" << xmlEscape(rel) << "\" alt=\"" << label << "\"><figcaption>"
      << label << "</figcaption></figure>";
}

void caseBlock(std::ostream& out, const CaseOutcome& o, const std::string& dir) {
  out << "<div class=\"case\" id=\"" << xmlEscape(o.name) << "\"><h3>" << xmlEscape(o.name)
      << " <span class=\"" << statusName(o.status) << "\">" << statusName(o.status) << "</span>"
      << (o.baseline == BaselineMatch::None
              ? std::string()
              : std::string(" (") + gateWord(o.baseline) + ": " + xmlEscape(o.baseline_note) + ")")
      << "</h3>\n";
  out << "<p>" << xmlEscape(o.headline) << "</p><p>rules:";
  for (const auto& r : o.rules) out << ' ' << xmlEscape(r);
  out << " &middot; device " << o.device_seconds << " s, model " << o.model_seconds << " s</p>\n";
  if (!o.verdict.findings.empty()) {
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
  undefinedTable(out, o);
  for (const std::string& im : o.images) {
    out << "<div class=\"images\">";
    imageFigure(out, dir, o.name + "/device/" + im + ".png", "device");
    imageFigure(out, dir, o.name + "/model/" + im + ".png", "model");
    imageFigure(out, dir, o.name + "/diff/" + im + ".png", "difference");
    out << "</div>\n";
  }
  if (!o.failing_rays.empty()) {
    out << "<table><tr><th>ray</th><th>x</th><th>y</th><th>field</th><th>device</th><th>model</"
           "th></tr>\n";
    for (const RayRow& r : o.failing_rays)
      out << "<tr><td>" << r.ray << "</td><td>" << r.x << "</td><td>" << r.y << "</td><td>"
          << xmlEscape(r.field) << "</td><td>" << xmlEscape(r.device) << "</td><td>"
          << xmlEscape(r.model) << "</td></tr>\n";
    out << "</table>\n";
  }
  out << "</div>\n";
}

}  // namespace

std::string writeReportHtml(const std::vector<CaseOutcome>& outcomes, const RunInfo& info,
                            const std::string& path) {
  const std::string dir = std::filesystem::path(path).parent_path().string();
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>rayspec "
         "report</title><style>"
      << kStyle << "</style><script>" << kCheckScript
      << "</script></head><body>\n<h1>rayspec report</h1>\n";
  out << "<p>device: " << xmlEscape(info.device) << " (ICD "
      << xmlEscape(info.icd.empty() ? "unknown" : info.icd) << ") &middot; model: embree "
      << xmlEscape(info.model_tier) << " tier &middot; validation layer "
      << (info.validation ? "on" : "off") << " &middot; " << xmlEscape(info.started) << "</p>\n";
  out << "<p id=\"completeness\"" << (info.interrupted ? " class=\"Fail\"" : "") << ">"
      << xmlEscape(runCompleteness(outcomes, info)) << "</p>\n";
  std::map<Status, int> counts;
  for (const CaseOutcome& o : outcomes) ++counts[o.status];
  out << "<table><tr>";
  for (const auto& [s, n] : counts)
    out << "<th class=\"" << statusName(s) << "\">" << statusName(s) << "</th>";
  out << "</tr><tr>";
  for (const auto& [s, n] : counts) out << "<td>" << n << "</td>";
  out << "</tr></table>\n";
  for (const std::string& e : info.teardown_errors)
    out << "<p class=\"Fail\">validation error at device teardown: " << xmlEscape(e) << "</p>\n";

  out << "<h2>Failing cases</h2>\n";
  int shown = 0;
  for (const CaseOutcome& o : outcomes)
    if (failing(o)) caseBlock(out, o, dir), ++shown;
  if (!shown) out << "<p>None.</p>\n";
  bool case_errors = false;
  for (const CaseOutcome& o : outcomes)
    if (o.status == Status::CaseError) {
      if (!case_errors)
        out << "<h2>Case errors</h2>\n<p>The case itself is at fault (a malformed file, or "
               "undefined behaviour the model found in it): the device is not blamed.</p>\n";
      case_errors = true;
      caseBlock(out, o, dir);
    }
  out << "<h2>Other cases</h2><button id=\"toggle\">show / hide</button><div id=\"passing\">\n";
  for (const CaseOutcome& o : outcomes)
    if (!failing(o) && o.status != Status::CaseError) caseBlock(out, o, dir);
  out << "</div>\n<h2>Rule "
         "coverage</h2>\n<table><tr><th>rule</th><th>title</th><th>cases</th></tr>\n";
  for (const auto& [label, cases] : info.coverage) {
    std::string title = "(not in the catalog)";
    for (const Rule& r : info.catalog)
      if (r.label == label) title = r.title;
    out << "<tr><td" << (cases.empty() ? " class=\"uncovered\"" : "") << ">" << xmlEscape(label)
        << "</td><td>" << xmlEscape(title) << "</td><td>";
    for (const auto& c : cases)
      out << "<a href=\"#" << xmlEscape(c) << "\">" << xmlEscape(c) << "</a> ";
    out << (cases.empty() ? "uncovered" : "") << "</td></tr>\n";
  }
  out << "</table>\n<script>" << kScript << "</script>\n</body></html>\n";
  std::ofstream file(path);
  file << out.str();
  return file ? std::string() : "cannot write " + path;
}

}  // namespace rayspec
