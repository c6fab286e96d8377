// What a driver is known to do, for regression checks (deqp-runner's three
// files, kept per driver in references/baselines/):
//   <driver>.csv         expected results: `case,Status` lines (rayspec status
//                        names, the name a CSV field as results.csv writes it),
//                        '#' comments saying why; a case not listed is
//                        expected to pass
//   <driver>-flakes.txt  regular expressions (RE2 syntax: linear-time
//                        matching, no back-references; one a line, found
//                        anywhere in the name unless anchored): cases known to
//                        give different results run to run
//   <driver>-skips.txt   regular expressions: cases not to run on this driver
//                        (each reported as NotSupported, never as a pass)
// The gate (report/baseline_gate.h) judges each outcome against them. The
// files are untrusted input: read line by line (a UTF-8 BOM dropped, CRLF
// taken), at most kMaxBaselineBytes, and matched by RE2, which takes time
// linear in the name whatever the pattern.
#pragma once

#include "base/result.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "compare/verdict.h"

namespace re2 {
class RE2;
}

namespace rayspec {

// One regular expression of a flakes or skips file, with where it came from.
struct NamePattern {
  std::string text;   // as written
  std::string where;  // "file:line"
  std::shared_ptr<const re2::RE2> regex;
};

constexpr size_t kMaxBaselineBytes = 16u << 20;

struct Baseline {
  std::string file, flakes_file, skips_file;  // "" when not used
  std::string through_file;                   // entries added for a --through path ("": none)
  std::map<std::string, Status> expected;     // case name -> status
  std::map<std::string, int> line_of;         // case name -> its line in `file`
  std::vector<NamePattern> flakes, skips;
  bool empty() const { return file.empty() && flakes_file.empty() && skips_file.empty(); }
};

// Reads a baseline CSV, or the error naming the file and line of a malformed
// entry or of a case listed twice.
Result<Baseline> loadBaseline(const std::string& path);

// The entries of the baseline CSV that name no case of `cases` (a case renamed
// or removed: its expectation would never apply), as "file:line: NAME ...".
std::vector<std::string> unknownEntries(const Baseline& b, const std::vector<std::string>& cases);

// Reads a flakes or skips file, or the error naming the file and line of a
// regular expression that does not compile.
Result<std::vector<NamePattern>> loadNamePatterns(const std::string& path);

// The first pattern found in `name`, or nullptr.
const NamePattern* findPattern(const std::vector<NamePattern>& patterns, const std::string& name);

// The flakes and skips files that go with a baseline CSV when none are named:
// <stem>-flakes.txt and <stem>-skips.txt beside it, if they exist ("" if not).
std::string siblingFile(const std::string& baseline_csv, const std::string& suffix);

// The whole set: the CSV (may be ""), and the flakes and skips files (given,
// or the CSV's siblings), or the first problem, naming file and line. With
// `through` (a --through feature path's name), the entries of
// <stem>-through-<through>.csv beside the CSV, if it exists, are added over
// the CSV's: what that path changes for this driver (Baseline::through_file).
Result<Baseline> loadBaselineSet(const std::string& csv, std::string flakes, std::string skips,
                                 const std::string& through = "");

}  // namespace rayspec
