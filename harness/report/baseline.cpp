#include "report/baseline.h"

#include <filesystem>
#include <fstream>

#include "report/escape.h"

namespace rayspec {
namespace {

// Calls line(text, number) for each line that is neither blank nor a comment;
// false when the file cannot be read.
template <typename F>
bool forEachEntry(const std::string& path, F line) {
  std::ifstream in(path);
  if (!in) return false;
  static const std::regex blank(R"(^\s*(#.*)?$)");
  std::string text;
  for (int number = 1; std::getline(in, text); ++number) {
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (std::regex_match(text, blank)) continue;
    if (!line(text, number)) break;
  }
  return true;
}

}  // namespace

Baseline loadBaseline(const std::string& path, std::string* error) {
  Baseline b;
  b.file = path;
  // An entry: `case,Status` (the case name a CSV field as results.csv writes
  // it, quoted when it holds a comma) and maybe a comment.
  static const std::regex entry(std::string("^(") + kCsvFieldPattern + R"(),\s*([A-Za-z]+)\s*(#.*)?$)");
  const bool read = forEachEntry(path, [&](const std::string& line, int number) {
    std::smatch m;
    Status s;
    if (!std::regex_match(line, m, entry) || !parseStatus(m[2], &s)) {
      *error = path + ":" + std::to_string(number) + ": expected 'case,Status' with a rayspec status, got '" + line + "'";
      return false;
    }
    b.expected[csvFieldText(m[1])] = s;
    return true;
  });
  if (!read) *error = "cannot read baseline " + path;
  return b;
}

std::vector<NamePattern> loadNamePatterns(const std::string& path, std::string* error) {
  std::vector<NamePattern> out;
  const bool read = forEachEntry(path, [&](const std::string& line, int number) {
    // A pattern may carry a trailing comment after whitespace and '#'.
    std::string text = std::regex_replace(line, std::regex(R"(\s+#.*$)"), "");
    text = std::regex_replace(text, std::regex(R"(^\s+|\s+$)"), "");
    const std::string where = path + ":" + std::to_string(number);
    try {
      out.push_back({text, where, std::regex(text, std::regex::ECMAScript)});
    } catch (const std::regex_error& e) {
      *error = where + ": not a regular expression: '" + text + "' (" + e.what() + ")";
      return false;
    }
    return true;
  });
  if (!read) *error = "cannot read " + path;
  return out;
}

const NamePattern* findPattern(const std::vector<NamePattern>& patterns, const std::string& name) {
  for (const NamePattern& p : patterns)
    if (std::regex_search(name, p.regex)) return &p;
  return nullptr;
}

std::string siblingFile(const std::string& baseline_csv, const std::string& suffix) {
  if (baseline_csv.empty()) return {};
  std::filesystem::path p(baseline_csv);
  const std::filesystem::path sibling = p.parent_path() / (p.stem().string() + suffix);
  return std::filesystem::exists(sibling) ? sibling.string() : std::string();
}

Baseline loadBaselineSet(const std::string& csv, std::string flakes, std::string skips, std::string* error) {
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
