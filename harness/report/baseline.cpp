#include "report/baseline.h"

#include <re2/re2.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "base/visible_text.h"
#include "report/escape.h"
#include "results/file_name.h"

namespace rayspec {
namespace {

std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t\r") + 1 - a);
}

// Calls line(text, number) for each line that is neither blank nor a comment
// (a UTF-8 BOM before the first line dropped); error: the file cannot be read
// or is too large. line returns false to stop.
template <typename F>
void forEachEntry(const std::string& path, std::string* error, F line) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in) {
    *error = "cannot read " + path;
    return;
  }
  if (size > kMaxBaselineBytes) {
    *error = path + ": " + std::to_string(size) + " bytes (at most " +
             std::to_string(kMaxBaselineBytes) + ")";
    return;
  }
  std::string text;
  for (int number = 1; std::getline(in, text); ++number) {
    if (number == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    if (!text.empty() && text.back() == '\r') text.pop_back();
    const std::string t = trimmed(text);
    if (t.empty() || t[0] == '#') continue;
    if (!line(text, number)) return;
  }
}

// What a line shows in a message: at most 120 bytes, invisible bytes as \xNN.
std::string shown(const std::string& line) {
  const std::string out = visibleText(line.substr(0, 120));
  return line.size() > 120 ? out + "... (" + std::to_string(line.size()) + " bytes)" : out;
}

}  // namespace

Baseline loadBaseline(const std::string& path, std::string* error) {
  Baseline b;
  b.file = path;
  // An entry: `case,Status` (the case name a CSV field as results.csv writes
  // it, quoted when it holds a comma) and maybe a comment.
  static const RE2 entry(std::string("(") + kCsvFieldPattern + R"(),\s*([A-Za-z]+)\s*(#.*)?)");
  std::map<std::string, int>& line_of = b.line_of;
  forEachEntry(path, error, [&](const std::string& line, int number) {
    std::string field, status;
    Status s;
    const std::string where = path + ":" + std::to_string(number);
    if (!RE2::FullMatch(line, entry, &field, &status, nullptr) || !parseStatus(status, &s)) {
      *error = where + ": expected 'case,Status' with a rayspec status, got '" + shown(line) + "'";
      return false;
    }
    const std::string name = csvFieldText(field);
    if (const std::string problem = caseNameProblem(name); !problem.empty()) {
      *error = where + ": '" + shown(name) + "' is not a case name: " + problem;
      return false;
    }
    if (const auto [it, fresh] = line_of.emplace(name, number); !fresh) {
      *error = where + ": " + name + " is listed again (first on line " +
               std::to_string(it->second) + ")";
      return false;
    }
    b.expected[name] = s;
    return true;
  });
  return b;
}

std::vector<std::string> unknownEntries(const Baseline& b, const std::vector<std::string>& cases) {
  const std::set<std::string> known(cases.begin(), cases.end());
  std::vector<std::string> out;
  for (const auto& [name, line] : b.line_of)
    if (!known.count(name))
      out.push_back(b.file + ":" + std::to_string(line) + ": " + name +
                    " is no case of the library (renamed or removed?)");
  return out;
}

std::vector<NamePattern> loadNamePatterns(const std::string& path, std::string* error) {
  std::vector<NamePattern> out;
  static const RE2 comment(R"(\s+#.*$)");
  forEachEntry(path, error, [&](const std::string& line, int number) {
    // A pattern may carry a trailing comment after whitespace and '#'.
    std::string text = line;
    RE2::Replace(&text, comment, "");
    text = trimmed(text);
    const std::string where = path + ":" + std::to_string(number);
    RE2::Options options;
    options.set_log_errors(false);
    auto regex = std::make_shared<const RE2>(text, options);
    if (!regex->ok()) {
      *error = where + ": not a regular expression (RE2 syntax): '" + shown(text) + "' (" +
               regex->error() + ")";
      return false;
    }
    out.push_back({text, where, std::move(regex)});
    return true;
  });
  return out;
}

const NamePattern* findPattern(const std::vector<NamePattern>& patterns, const std::string& name) {
  for (const NamePattern& p : patterns)
    if (RE2::PartialMatch(name, *p.regex)) return &p;
  return nullptr;
}

std::string siblingFile(const std::string& baseline_csv, const std::string& suffix) {
  if (baseline_csv.empty()) return {};
  std::filesystem::path p(baseline_csv);
  const std::filesystem::path sibling = p.parent_path() / (p.stem().string() + suffix);
  return std::filesystem::exists(sibling) ? sibling.string() : std::string();
}

Baseline loadBaselineSet(const std::string& csv, std::string flakes, std::string skips,
                         std::string* error) {
  Baseline b;
  if (!csv.empty()) b = loadBaseline(csv, error);
  if (!error->empty()) return b;
  if (flakes.empty()) flakes = siblingFile(csv, "-flakes.txt");
  if (skips.empty()) skips = siblingFile(csv, "-skips.txt");
  if (!flakes.empty()) {
    b.flakes_file = flakes;
    b.flakes = loadNamePatterns(flakes, error);
    if (!error->empty()) return b;
  }
  if (!skips.empty()) {
    b.skips_file = skips;
    b.skips = loadNamePatterns(skips, error);
  }
  return b;
}

}  // namespace rayspec
