#include "report/baseline.h"

#include <fstream>

namespace rayspec {

Baseline loadBaseline(const std::string& path, std::string* error) {
  Baseline b;
  b.file = path;
  std::ifstream in(path);
  if (!in) {
    *error = "cannot read baseline " + path;
    return b;
  }
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
    if (line.empty()) continue;
    const size_t comma = line.find(',');
    Status s;
    if (comma == std::string::npos || !parseStatus(line.substr(comma + 1), &s)) {
      *error = path + ":" + std::to_string(number) + ": expected 'case,Status' with a rayspec status, got '" + line + "'";
      return b;
    }
    b.expected[line.substr(0, comma)] = s;
  }
  return b;
}

void applyBaseline(const Baseline& baseline, CaseOutcome& o) {
  const auto it = baseline.expected.find(o.name);
  if (it == baseline.expected.end()) return;
  if (o.status == it->second) {
    o.baseline = BaselineMatch::Expected;
  } else if (o.status == Status::Pass) {
    o.baseline = BaselineMatch::UnexpectedPass;
  }
}

}  // namespace rayspec
