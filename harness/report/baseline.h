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
// linear in the name whatever the pattern; a flakes or skips file's patterns
// hold at most kMaxPatternBytes (comments aside) and compile together to at
// most kMaxPatternInstructions (one RE2::Set, its memory within
// kPatternSetMemory), so a file of patterns that each compile large
// (x[a-z]{1000}) or parse large ((?:) repeated) is refused at the line that
// passes a bound instead of taking gigabytes.
#pragma once

#include "base/result.h"

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "compare/verdict.h"

namespace rayspec {

// One regular expression of a flakes or skips file, with where it came from.
struct NamePattern {
  std::string text;   // as written
  std::string where;  // "file:line"
};

// The patterns of one flakes or skips file, compiled together.
struct CompiledPatterns;  // an RE2::Set of them all (report/baseline.cpp)
struct NamePatterns {
  std::vector<NamePattern> list;                     // in the file's order
  std::shared_ptr<const CompiledPatterns> compiled;  // null when list is empty
  size_t size() const { return list.size(); }
  bool empty() const { return list.empty(); }
};

constexpr size_t kMaxBaselineBytes = 16u << 20;
// RE2's max_mem for one file's patterns together (the compiled program and
// the memory of its DFA), and the most instructions they may compile to: a
// 32nd of what RE2 would let the set's program take (max_mem at 8 bytes an
// instruction), so nearly all of max_mem is left to its DFA's states.
constexpr int64_t kPatternSetMemory = 64ll << 20;
constexpr int64_t kMaxPatternInstructions = kPatternSetMemory / 256;
// The most text a flakes or skips file's patterns may hold together: RE2
// keeps each one's parse until the set compiles (about 200 bytes a byte of
// `|`), and its compiler crashed on 1 MiB of them.
constexpr int64_t kMaxPatternBytes = 256 << 10;

struct Baseline {
  std::string file, flakes_file, skips_file;  // "" when not used
  std::string through_file;                   // entries added for a --through path ("": none)
  std::map<std::string, Status> expected;     // case name -> status
  std::map<std::string, int> line_of;         // case name -> its line in `file`
  NamePatterns flakes, skips;
  bool empty() const { return file.empty() && flakes_file.empty() && skips_file.empty(); }
};

// Reads a baseline CSV, or the error naming the file and line of a malformed
// entry or of a case listed twice.
Result<Baseline> loadBaseline(const std::string& path);

// The entries of the baseline CSV that name no case of `cases` (a case renamed
// or removed: its expectation would never apply), as "file:line: NAME ...".
std::vector<std::string> unknownEntries(const Baseline& b, const std::vector<std::string>& cases);

// Reads a flakes or skips file, or the error naming the file and line of a
// regular expression that does not compile, or of the one whose program
// takes the file's patterns past kMaxPatternInstructions.
Result<NamePatterns> loadNamePatterns(const std::string& path);

// The first pattern (in the file's order) found in `name`, or nullptr.
const NamePattern* findPattern(const NamePatterns& patterns, const std::string& name);

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
