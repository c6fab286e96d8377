// Table, JSON and plot panels of the stability report.
#include "stability/stability_table.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "base/visible_text.h"
#include "tiers/tier_runs.h"

namespace rayspec {
namespace {

std::vector<std::string> families(const std::vector<StabilityEntry>& entries) {
  std::vector<std::string> out;
  for (const StabilityEntry& e : entries)
    if (std::find(out.begin(), out.end(), e.family) == out.end()) out.push_back(e.family);
  return out;
}

// The family's magnitudes, ascending, with their text.
std::vector<std::pair<double, std::string>> magnitudes(const std::vector<StabilityEntry>& entries,
                                                       const std::string& family) {
  std::map<double, std::string> m;
  for (const StabilityEntry& e : entries)
    if (e.family == family) m.emplace(e.magnitude, e.magnitude_text);
  return {m.begin(), m.end()};
}

const StabilityEntry* find(const std::vector<StabilityEntry>& entries, const std::string& family,
                           double magnitude, const std::string& source) {
  for (const StabilityEntry& e : entries)
    if (e.family == family && e.magnitude == magnitude && e.source == source) return &e;
  return nullptr;
}

}  // namespace

std::string stabilityDeviceSource(const std::string& device, const std::string& driver) {
  if (driver.empty()) return visibleLine(device);
  return shortDeviceName(device) + " " + shortDeviceName(driver);
}

void addCounts(std::vector<StabilityEntry>& entries, const StabilityEntry& e) {
  for (StabilityEntry& x : entries)
    if (x.family == e.family && x.magnitude == e.magnitude && x.source == e.source) {
      x.counts.add(e.counts);
      return;
    }
  entries.push_back(e);
}

std::vector<std::string> stabilitySources(const std::vector<StabilityEntry>& entries) {
  std::vector<std::string> out;
  for (const StabilityEntry& e : entries)
    if (std::find(out.begin(), out.end(), e.source) == out.end()) out.push_back(e.source);
  return out;
}

namespace {
// A source's column: its two rates, or its name where that is wider (up to 40).
int columnWidth(const std::string& source) {
  return std::clamp(static_cast<int>(source.size()), 17, 40);
}
}  // namespace

std::string formatStabilityTable(const std::vector<StabilityEntry>& entries) {
  const std::vector<std::string> sources = stabilitySources(entries);
  char buf[128];
  std::string out = "Leaks and double hits per 1000 rays aimed inside the meshes (leak / double)\n";
  std::snprintf(buf, sizeof buf, "%-21s %9s %6s", "family", "magnitude", "rays");
  out += buf;
  for (const std::string& s : sources) {
    std::snprintf(buf, sizeof buf, " | %*s", columnWidth(s), s.substr(0, 40).c_str());
    out += buf;
  }
  out += "\n";
  for (const std::string& f : families(entries))
    for (const auto& [m, text] : magnitudes(entries, f)) {
      uint64_t rays = 0;
      for (const std::string& s : sources)
        if (const StabilityEntry* e = find(entries, f, m, s)) rays = std::max(rays, e->counts.rays);
      std::snprintf(buf, sizeof buf, "%-21s %9s %6llu", f.c_str(), text.c_str(),
                    (unsigned long long)rays);
      out += buf;
      for (const std::string& s : sources) {
        const StabilityEntry* e = find(entries, f, m, s);
        if (e)
          std::snprintf(buf, sizeof buf, " | %*.1f %8.1f", columnWidth(s) - 9, e->counts.leakRate(),
                        e->counts.doubleRate());
        else
          std::snprintf(buf, sizeof buf, " | %*s", columnWidth(s), "-");
        out += buf;
      }
      out += "\n";
    }
  return out;
}

nlohmann::json stabilityJson(const std::vector<StabilityEntry>& entries) {
  nlohmann::json rows = nlohmann::json::array();
  for (const StabilityEntry& e : entries)
    rows.push_back({{"family", e.family},
                    {"magnitude", e.magnitude},
                    {"magnitude_text", e.magnitude_text},
                    {"source", e.source},
                    {"rays", e.counts.rays},
                    {"leaks", e.counts.leaks},
                    {"double_hits", e.counts.doubles},
                    {"leaks_per_1000", e.counts.leakRate()},
                    {"double_hits_per_1000", e.counts.doubleRate()}});
  return {{"unit", "per 1000 rays"}, {"sources", stabilitySources(entries)}, {"entries", rows}};
}

// Small multiples: a row per family, a column per source (each model tier,
// each device), each panel its leaks and double hits against the magnitude.
// The panels of a row share the y axis, so sources compare at a glance.
std::vector<PlotPanel> stabilityPanels(const std::vector<StabilityEntry>& entries) {
  std::vector<PlotPanel> panels;
  for (const std::string& f : families(entries)) {
    double row_max = 0;
    const size_t first = panels.size();
    for (const std::string& s : stabilitySources(entries)) {
      PlotPanel p;
      p.title = f + ": " + s;
      p.x_label = f == "scale" ? "scale (mesh extent)" : "coordinate magnitude";
      p.y_label = "per 1000 rays";
      p.log_x = true;
      PlotSeries leaks{"leaks", {}}, doubles{"double hits", {}};
      for (const auto& [m, text] : magnitudes(entries, f))
        if (const StabilityEntry* e = find(entries, f, m, s)) {
          leaks.points.push_back({m, e->counts.leakRate()});
          doubles.points.push_back({m, e->counts.doubleRate()});
          row_max = std::max({row_max, e->counts.leakRate(), e->counts.doubleRate()});
        }
      p.series = {std::move(leaks), std::move(doubles)};
      panels.push_back(std::move(p));
    }
    for (size_t k = first; k < panels.size(); ++k)
      panels[k].y_max = row_max > 0 ? row_max * 1.08 : 1;
  }
  return panels;
}

}  // namespace rayspec
