// Table, JSON and plot panels of the accuracy report.
#include "accuracy/accuracy_table.h"

#include <cstdio>

namespace rayspec {

const char* caseSetName(CaseSet s) {
  return nameOf(s);
}
const char* sourceKindName(SourceKind k) {
  return nameOf(k);
}

void addToRow(std::vector<AccuracyRow>& rows, const AccuracyRow& one) {
  for (AccuracyRow& r : rows)
    if (r.set == one.set && r.source == one.source) {
      r.cases += one.cases;
      r.launch_rays += one.launch_rays;
      r.trace_seconds += one.trace_seconds;
      r.d.add(one.d);
      return;
    }
  rows.push_back(one);
}

std::string formatAccuracyTable(const std::vector<AccuracyRow>& rows) {
  std::string out =
      "Disagreements with the model's exact tier per ray, and trace time per million rays\n(leak: "
      "exact hit, other missed a closed surface; double: exact ran any-hit once, other more;\n "
      "other prim: both hit, another primitive/instance; extra: exact missed a clear ray, other "
      "hit;\n t error: |t - t_exact| in float ULPs of t_exact where both hit the same primitive)\n";
  char buf[256];
  for (CaseSet set : {CaseSet::Ordinary, CaseSet::Hard}) {
    bool any = false;
    for (const AccuracyRow& r : rows) any = any || r.set == set;
    if (!any) continue;
    std::snprintf(buf, sizeof buf,
                  "\n%s cases\n%-14s %5s %9s %10s %9s %7s %7s %7s %7s %8s %8s %10s\n",
                  caseSetName(set), "source", "cases", "rays", "ms/Mray", "dis/Mray", "leaks",
                  "double", "o.prim", "extra", "t med", "t p99", "t max");
    out += buf;
    for (const AccuracyRow& r : rows) {
      if (r.set != set) continue;
      std::snprintf(buf, sizeof buf,
                    "%-14s %5llu %9llu %10.2f %9.1f %7llu %7llu %7llu %7llu %8.3g %8.3g %10.4g\n",
                    r.source.substr(0, 14).c_str(), (unsigned long long)r.cases,
                    (unsigned long long)r.d.rays, r.msPerMray(), r.d.perMillion(),
                    (unsigned long long)r.d.leaks, (unsigned long long)r.d.double_hits,
                    (unsigned long long)r.d.other_primitive, (unsigned long long)r.d.extra_hits,
                    r.d.t.median(), r.d.t.p99(), r.d.t.max());
      out += buf;
    }
  }
  out += "\nt error histogram (rays per bin; bin: at most this many ULP)\n";
  std::snprintf(buf, sizeof buf, "%-8s %-14s", "set", "source");
  out += buf;
  for (size_t b = 0; b < kTErrorBins; ++b) {
    std::snprintf(buf, sizeof buf, " %7s", tErrorBinLabel(b).c_str());
    out += buf;
  }
  out += "\n";
  for (const AccuracyRow& r : rows) {
    std::snprintf(buf, sizeof buf, "%-8s %-14s", caseSetName(r.set),
                  r.source.substr(0, 14).c_str());
    out += buf;
    for (uint64_t n : r.d.t.histogram()) {
      std::snprintf(buf, sizeof buf, " %7llu", (unsigned long long)n);
      out += buf;
    }
    out += "\n";
  }
  return out;
}

nlohmann::json accuracyJson(const std::vector<AccuracyRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const AccuracyRow& r : rows) {
    nlohmann::json hist = nlohmann::json::array();
    for (size_t b = 0; b < kTErrorBins; ++b)
      hist.push_back({{"max_ulp", tErrorBinLabel(b)}, {"rays", r.d.t.histogram()[b]}});
    out.push_back({{"set", caseSetName(r.set)},
                   {"source", r.source},
                   {"kind", sourceKindName(r.kind)},
                   {"cases", r.cases},
                   {"launch_rays", r.launch_rays},
                   {"rays", r.d.rays},
                   {"trace_seconds", r.trace_seconds},
                   {"ms_per_mray", r.msPerMray()},
                   {"disagreeing_rays", r.d.disagreeing},
                   {"disagreeing_per_mray", r.d.perMillion()},
                   {"leaks", r.d.leaks},
                   {"double_hits", r.d.double_hits},
                   {"other_primitive", r.d.other_primitive},
                   {"extra_hits", r.d.extra_hits},
                   {"t_error_ulp",
                    {{"rays", r.d.t.count()},
                     {"median", r.d.t.median()},
                     {"p99", r.d.t.p99()},
                     {"max", r.d.t.max()},
                     {"histogram", hist}}}});
  }
  return {{"reference", "model exact"}, {"rows", out}};
}

std::vector<PlotPanel> accuracyPanels(const std::vector<AccuracyRow>& rows) {
  std::vector<PlotPanel> panels;
  for (CaseSet set : {CaseSet::Ordinary, CaseSet::Hard}) {
    PlotPanel p;
    p.title = std::string(caseSetName(set)) + " cases";
    p.x_label = "trace ms per million rays (no disagreement: drawn at 0.1)";
    p.y_label = "disagreeing rays / Mray";
    p.log_x = p.log_y = true;
    p.lines = false;
    for (const AccuracyRow& r : rows) {
      if (r.set != set || r.launch_rays == 0) continue;
      const double y = r.d.disagreeing ? r.d.perMillion() : kPlotFloorPerMillion;
      p.series.push_back(
          {r.source, {{r.msPerMray(), y}}, r.d.disagreeing ? r.source : r.source + " (0)"});
    }
    if (!p.series.empty()) panels.push_back(std::move(p));
  }
  return panels;
}

}  // namespace rayspec
