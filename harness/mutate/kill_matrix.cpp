#include "mutate/kill_matrix.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include <nlohmann/json.hpp>

#include "base/visible_text.h"

namespace rayspec {
namespace {

std::string percent(size_t part, size_t whole) {
  if (!whole) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.1f%%",
                100.0 * static_cast<double>(part) / static_cast<double>(whole));
  return text;
}

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", s);
  return text;
}

std::string cellText(const KillCell& c) {
  if (!c.applied) return ".";
  return std::to_string(c.killed) + "/" + std::to_string(c.applied);
}

std::string padded(std::string s, size_t width) {
  if (s.size() < width) s.insert(0, width - s.size(), ' ');
  return s;
}

}  // namespace

size_t KillMatrix::unexplained() const {
  return static_cast<size_t>(std::count_if(survivors.begin(), survivors.end(),
                                           [](const Survivor& s) { return s.reason.empty(); }));
}

KillMatrix buildKillMatrix(const std::vector<CaseMutation>& cases) {
  KillMatrix m;
  std::set<std::string> families;
  for (const CaseMutation& c : cases) {
    ++m.cases;
    size_t applied = 0;
    for (const LegalDevice& d : c.legal_devices) {
      if (!d.applied) continue;
      ++applied;
      if (d.false_alarm) m.false_alarms.push_back({c.name, d.name, d.rule, d.headline, d.ray});
    }
    m.legal_variants += applied;
    m.legal_cases += applied ? 1 : 0;
    m.legal_seconds += c.legal_seconds;
    m.mutant_seconds += c.mutant_seconds;
    if (!c.judged) {
      m.not_judged.push_back({c.name, c.not_judged});
      continue;
    }
    ++m.judged;
    families.insert(c.family);
    for (const MutantOutcome& o : c.mutants) {
      if (!o.mutation.applied) continue;
      for (KillCell* cell : {&m.cells[o.kind][c.family], &m.by_kind[o.kind]}) {
        ++cell->applied;
        if (o.killed)
          ++cell->killed;
        else if (!o.legal_reason.empty())
          ++cell->legal;
      }
      if (!o.killed) m.survivors.push_back({c.name, o.name, o.mutation.what, o.legal_reason});
    }
  }
  m.families.assign(families.begin(), families.end());
  return m;
}

std::string killMatrixText(const KillMatrix& m) {
  std::string out =
      "Kill matrix: killed/applied per mutant kind (rows) and case family (columns)\n";
  size_t width = 6;
  for (const std::string& f : m.families) width = std::max(width, f.size() + 1);
  std::string header = padded("", 22);
  for (const std::string& f : m.families) header += padded(f, width);
  out += header + padded("total", 12) + padded("killed", 8) + padded("legal", 8) + "\n";
  size_t applied = 0, killed = 0, legal = 0;
  for (const auto& [kind, row] : m.cells) {
    std::string line = kind;
    line.resize(22, ' ');
    for (const std::string& f : m.families) {
      const auto it = row.find(f);
      line += padded(it == row.end() ? "." : cellText(it->second), width);
    }
    const KillCell& k = m.by_kind.at(kind);
    line += padded(cellText(k), 12) + padded(percent(k.killed, k.applied), 8) +
            padded(percent(k.killed + k.legal, k.applied), 8);
    out += line + "\n";
    applied += k.applied;
    killed += k.killed;
    legal += k.legal;
  }
  out += "\nScore: " + std::to_string(killed) + " of " + std::to_string(applied) +
         " (case, mutant) pairs killed (" + percent(killed, applied) + "); " +
         std::to_string(legal) + " survive legally, " + std::to_string(m.unexplained()) +
         " survive with no reason (holes)\n";
  out += "Null device: killed on " + std::to_string(m.nullKilled()) + " of " +
         std::to_string(m.judged) + " judged cases (" + percent(m.nullKilled(), m.judged) + ")";
  if (m.nullApplied() < m.judged)
    out += "; on " + std::to_string(m.judged - m.nullApplied()) +
           " it changes nothing: their device answer is all zero (a launch with no rays)";
  out += "\n";
  out += std::to_string(m.judged) + " of " + std::to_string(m.cases) + " cases judged";
  out += m.not_judged.empty() ? "\n" : "; not judged:\n";
  for (const auto& [name, why] : m.not_judged) out += "  " + name + ": " + visibleLine(why) + "\n";
  out += "Legal devices: " + std::to_string(m.false_alarms.size()) + " false alarms of " +
         std::to_string(m.legal_variants) + " variants (" + std::to_string(m.legal_cases) +
         " cases)\n";
  out += "Time, summed over the cases: legal devices " + seconds(m.legal_seconds) +
         ", generic mutants " + seconds(m.mutant_seconds) + "\n";
  for (const FalseAlarm& a : m.false_alarms)
    out += "  false alarm: " + a.case_name + "  " + a.device + "  ray " +
           (a.ray < 0 ? std::string("-") : std::to_string(a.ray)) + "  " + a.rule + ": " +
           visibleLine(a.headline) + "\n";
  if (m.unexplained()) {
    out += "\nSurvivors with no reason (holes):\n";
    for (const Survivor& s : m.survivors)
      if (s.reason.empty()) out += "  " + s.case_name + "  " + s.mutant + "  (" + s.what + ")\n";
  }
  return out;
}

std::string killMatrixJson(const KillMatrix& m, const std::string& run_dir,
                           const std::string& device) {
  nlohmann::json j;
  j["run"] = run_dir;
  j["device"] = device;
  j["cases"] = m.cases;
  j["judged"] = m.judged;
  j["null_device_killed"] = m.nullKilled();
  j["unexplained_survivors"] = m.unexplained();
  for (const auto& [kind, row] : m.cells)
    for (const auto& [family, cell] : row)
      j["matrix"][kind][family] = {
          {"applied", cell.applied}, {"killed", cell.killed}, {"legal", cell.legal}};
  for (const auto& [kind, cell] : m.by_kind)
    j["by_kind"][kind] = {
        {"applied", cell.applied}, {"killed", cell.killed}, {"legal", cell.legal}};
  j["survivors"] = nlohmann::json::array();
  for (const Survivor& s : m.survivors)
    j["survivors"].push_back(
        {{"case", s.case_name}, {"mutant", s.mutant}, {"what", s.what}, {"reason", s.reason}});
  j["seconds"] = {{"legal_devices", m.legal_seconds}, {"generic_mutants", m.mutant_seconds}};
  j["legal_devices"] = {{"variants", m.legal_variants},
                        {"cases", m.legal_cases},
                        {"false_alarms", nlohmann::json::array()}};
  for (const FalseAlarm& a : m.false_alarms)
    j["legal_devices"]["false_alarms"].push_back({{"case", a.case_name},
                                                  {"device", a.device},
                                                  {"rule", a.rule},
                                                  {"ray", a.ray},
                                                  {"headline", a.headline}});
  j["not_judged"] = nlohmann::json::array();
  for (const auto& [name, why] : m.not_judged)
    j["not_judged"].push_back({{"case", name}, {"why", why}});
  return j.dump(1) + "\n";
}

}  // namespace rayspec
