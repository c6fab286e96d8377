#include "report/baseline.h"

#include <fstream>
#include <regex>

#include "report/escape.h"

namespace rayspec {

Baseline loadBaseline(const std::string& path, std::string* error) {
  Baseline b;
  b.file = path;
  std::ifstream in(path);
  if (!in) {
    *error = "cannot read baseline " + path;
    return b;
  }
  // A line: blank, a comment, or `case,Status` (the case name a CSV field as
  // results.csv writes it, quoted when it holds a comma) and maybe a comment.
  static const std::regex blank(R"(^\s*(#.*)?$)");
  static const std::regex entry(std::string("^(") + kCsvFieldPattern + R"(),\s*([A-Za-z]+)\s*(#.*)?$)");
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (std::regex_match(line, blank)) continue;
    std::smatch m;
    Status s;
    if (!std::regex_match(line, m, entry) || !parseStatus(m[2], &s)) {
      *error = path + ":" + std::to_string(number) + ": expected 'case,Status' with a rayspec status, got '" + line + "'";
      return b;
    }
    b.expected[csvFieldText(m[1])] = s;
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
