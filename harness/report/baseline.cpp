#include "report/baseline.h"

#include <re2/re2.h>
#include <re2/set.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <tuple>

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
// (a UTF-8 BOM before the first line dropped), and stops at the first error
// it returns; an error too when the file cannot be read or is too large.
template <typename F>
Result<void> forEachEntry(const std::string& path, F line) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in) return errorMessage("cannot read " + path);
  if (size > kMaxBaselineBytes)
    return errorMessage(path + ": " + std::to_string(size) + " bytes (at most " +
                        std::to_string(kMaxBaselineBytes) + ")");
  std::string text;
  for (int number = 1; std::getline(in, text); ++number) {
    if (number == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    if (!text.empty() && text.back() == '\r') text.pop_back();
    const std::string t = trimmed(text);
    if (t.empty() || t[0] == '#') continue;
    if (Result<void> r = line(text, number); !r) return r;
  }
  return {};
}

// What a line shows in a message: at most 120 bytes, invisible bytes as \xNN.
std::string shown(const std::string& line) {
  return visibleText(line, 120);
}

}  // namespace

Result<Baseline> loadBaseline(const std::string& path) {
  Baseline b;
  b.file = path;
  // An entry: `case,Status` (the case name a CSV field as results.csv writes
  // it, quoted when it holds a comma) and maybe a comment.
  static const RE2 entry(std::string("(") + kCsvFieldPattern + R"(),\s*([A-Za-z]+)\s*(#.*)?)");
  std::map<std::string, int>& line_of = b.line_of;
  Result<void> read = forEachEntry(path, [&](const std::string& line, int number) -> Result<void> {
    std::string field, status;
    Status s;
    const std::string where = path + ":" + std::to_string(number);
    if (!RE2::FullMatch(line, entry, &field, &status, nullptr) || !parseStatus(status, &s))
      return errorMessage(where + ": expected 'case,Status' with a rayspec status, got '" +
                          shown(line) + "'");
    const std::string name = csvFieldText(field);
    if (const std::string problem = caseNameProblem(name); !problem.empty())
      return errorMessage(where + ": '" + shown(name) + "' is not a case name: " + problem);
    if (const auto [it, fresh] = line_of.emplace(name, number); !fresh)
      return errorMessage(where + ": " + name + " is listed again (first on line " +
                          std::to_string(it->second) + ")");
    b.expected[name] = s;
    return {};
  });
  if (!read) return read.error();
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

struct CompiledPatterns {
  RE2::Set set;
};

namespace {

RE2::Options patternOptions(int64_t max_mem) {
  RE2::Options options;
  options.set_log_errors(false);
  options.set_max_mem(max_mem);
  return options;
}

// The error at `where` when the patterns up to `text` compile to more than
// kMaxPatternInstructions (`instructions`: how many, or 0 when RE2 refused
// the one alone).
Error tooLarge(const std::string& where, const std::string& text, int64_t instructions) {
  const std::string what =
      instructions ? "the patterns up to this one compile to " + std::to_string(instructions) +
                         " RE2 instructions, more than the "
                   : "this pattern alone compiles to more RE2 instructions than the ";
  return errorMessage(where + ": '" + shown(text) + "': " + what +
                      std::to_string(kMaxPatternInstructions) +
                      " a flakes or skips file may compile to");
}

// The error at `where` when the patterns up to `text` hold `bytes`, more
// than kMaxPatternBytes.
Error tooLong(const std::string& where, const std::string& text, int64_t bytes) {
  return errorMessage(where + ": '" + shown(text) + "': the patterns up to this one hold " +
                      std::to_string(bytes) + " bytes, more than the " +
                      std::to_string(kMaxPatternBytes) +
                      " a flakes or skips file may hold (comments aside)");
}

// For one pattern alone, a 16th of the set's memory: RE2 caps its program at
// two thirds of that at 8 bytes an instruction (349,525 instructions), more
// than kMaxPatternInstructions, so what it refuses alone is past them.
constexpr int64_t kOnePatternMemory = kPatternSetMemory / 16;

// How many instructions `text` compiles to alone, or the error at `where`.
Result<int64_t> compiledSize(const std::string& text, const std::string& where) {
  const RE2 regex(text, patternOptions(kOnePatternMemory));
  if (regex.error_code() == RE2::ErrorPatternTooLarge) return tooLarge(where, text, 0);
  if (!regex.ok())
    return errorMessage(where + ": not a regular expression (RE2 syntax): '" + shown(text) + "' (" +
                        regex.error() + ")");
  return regex.ProgramSize();
}

// The first of `patterns` found in `name`, each compiled alone: where the
// set's DFA gave up (it has room for its states, so this is not expected).
const NamePattern* findOneByOne(const NamePatterns& patterns, const std::string& name) {
  for (const NamePattern& p : patterns.list)
    if (RE2::PartialMatch(name, RE2(p.text, patternOptions(kOnePatternMemory)))) return &p;
  return nullptr;
}

}  // namespace

Result<NamePatterns> loadNamePatterns(const std::string& path) {
  NamePatterns out;
  auto compiled = std::make_shared<CompiledPatterns>(
      CompiledPatterns{RE2::Set(patternOptions(kPatternSetMemory), RE2::UNANCHORED)});
  int64_t instructions = 0, bytes = 0;
  static const RE2 comment(R"(\s+#.*$)");
  Result<void> read = forEachEntry(path, [&](const std::string& line, int number) -> Result<void> {
    // A pattern may carry a trailing comment after whitespace and '#'.
    std::string text = line;
    RE2::Replace(&text, comment, "");
    text = trimmed(text);
    const std::string where = path + ":" + std::to_string(number);
    if ((bytes += static_cast<int64_t>(text.size())) > kMaxPatternBytes)
      return tooLong(where, text, bytes);
    RAYSPEC_TRY(const int64_t size, compiledSize(text, where));
    if ((instructions += size) > kMaxPatternInstructions)
      return tooLarge(where, text, instructions);
    std::string error;
    if (compiled->set.Add(text, &error) < 0)
      return errorMessage(where + ": not a regular expression (RE2 syntax): '" + shown(text) +
                          "' (" + error + ")");
    out.list.push_back({text, where});
    return {};
  });
  if (!read) return read.error();
  if (out.list.empty()) return out;
  if (!compiled->set.Compile())
    return errorMessage(path + ": its patterns do not compile together within RE2's " +
                        std::to_string(kPatternSetMemory) + " bytes");
  out.compiled = std::move(compiled);
  return out;
}

const NamePattern* findPattern(const NamePatterns& patterns, const std::string& name) {
  if (!patterns.compiled) return nullptr;
  std::vector<int> found;
  RE2::Set::ErrorInfo info{RE2::Set::kNoError};
  if (patterns.compiled->set.Match(name, &found, &info))
    return &patterns.list.at(static_cast<size_t>(*std::min_element(found.begin(), found.end())));
  return info.kind == RE2::Set::kNoError ? nullptr : findOneByOne(patterns, name);
}

std::string siblingFile(const std::string& baseline_csv, const std::string& suffix) {
  if (baseline_csv.empty()) return {};
  std::filesystem::path p(baseline_csv);
  const std::filesystem::path sibling = p.parent_path() / (p.stem().string() + suffix);
  return std::filesystem::exists(sibling) ? sibling.string() : std::string();
}

namespace {

// The file of what feature path `through` changes for the driver of
// baseline_csv: <driver>-through-<path>.csv. The ray query loops run from a
// compute shader (ray-query-compute) change what those loops change, so
// without a file of its own that path reads ray-query's.
std::string throughFile(const std::string& baseline_csv, const std::string& through) {
  if (through.empty()) return {};
  if (std::string own = siblingFile(baseline_csv, "-through-" + through + ".csv"); !own.empty())
    return own;
  const std::string compute = "-compute";
  if (through.size() > compute.size() &&
      through.compare(through.size() - compute.size(), compute.size(), compute) == 0)
    return siblingFile(baseline_csv,
                       "-through-" + through.substr(0, through.size() - compute.size()) + ".csv");
  return {};
}

}  // namespace

Result<Baseline> loadBaselineSet(const std::string& csv, std::string flakes, std::string skips,
                                 const std::string& through) {
  Baseline b;
  if (!csv.empty()) {
    Result<Baseline> read = loadBaseline(csv);
    if (!read) return read.error();
    b = std::move(*read);
  }
  if (const std::string path_file = throughFile(csv, through); !path_file.empty()) {
    Result<Baseline> read = loadBaseline(path_file);
    if (!read) return read.error();
    for (const auto& [name, status] : read->expected) b.expected[name] = status;
    b.through_file = path_file;
  }
  if (flakes.empty()) flakes = siblingFile(csv, "-flakes.txt");
  if (skips.empty()) skips = siblingFile(csv, "-skips.txt");
  for (auto [file, kept, patterns] : {std::tuple{flakes, &b.flakes_file, &b.flakes},
                                      std::tuple{skips, &b.skips_file, &b.skips}}) {
    if (file.empty()) continue;
    *kept = file;
    Result<NamePatterns> read = loadNamePatterns(file);
    if (!read) return read.error();
    *patterns = std::move(*read);
  }
  return b;
}

}  // namespace rayspec
