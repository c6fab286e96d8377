// The map of the Khronos CTS's ray tracing groups (references/cts-map.yaml):
// per mustpass list, per group, what the CTS varies there (its axes, read
// from the CTS sources) and the rayspec cases or --through paths that cover
// each axis, or why none does. The tables of docs/cts-map.md are generated
// from it (ctsMapDocument); the group counts come from the list's counts
// file under references/cts/ (the mustpass list counted, with its commit).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "base/result.h"

namespace rayspec {

// One thing the CTS varies within a group, and what of rayspec covers it.
struct CtsAxis {
  std::string axis;                  // what the CTS checks, in our words
  std::vector<std::string> cases;    // case globs (cases/) that cover it
  std::vector<std::string> through;  // --through paths that cover it
  std::string how;                   // what those cases do, where the axis does not say
  std::string not_covered;           // why nothing covers it ("" when covered)
  bool covered() const { return !cases.empty() || !through.empty(); }
};

struct CtsGroup {
  std::string group;   // the third part of a test name: dEQP-VK.<list>.<group>.*
  std::string source;  // the CTS source file that makes its tests
  std::vector<CtsAxis> axes;
};

struct CtsList {
  std::string name;         // ray_tracing_pipeline, ray_query
  std::string mustpass;     // the list's path in VK-GL-CTS
  std::string counts_file;  // its counts, relative to the folder above the map's folder
  std::vector<CtsGroup> groups;
};

// Full: every axis has a case or a path; none: no axis has; else partial.
enum class CtsCoverage { Full, Partial, None };
CtsCoverage groupCoverage(const CtsGroup& group);
const char* ctsCoverageName(CtsCoverage c);

// The counts of one mustpass list: `uniq -c` lines ("  COUNT GROUP") after
// '#' comments, one of which names the commit ("VK-GL-CTS commit SHA"); the
// closing "COUNT total" line is the list's length.
struct CtsCounts {
  std::string commit;
  std::map<std::string, long> tests;  // group -> tests
  long total = 0;
};

// The map, or the error naming the file, line and field.
Result<std::vector<CtsList>> loadCtsMap(const std::string& path);
// Where a list's counts file is: its path taken from the folder above the
// map's (references/cts-map.yaml -> the source folder).
std::string ctsCountsPath(const std::string& map_path, const CtsList& list);
Result<CtsCounts> loadCtsCounts(const std::string& path);

// What does not hold between a list and its counts: a group twice, a group
// the counts lack or a counted group the map lacks, counts that do not sum
// to the total, an axis neither covered nor said not covered, or both.
std::vector<std::string> ctsMapProblems(const CtsList& list, const CtsCounts& counts);

// The generated part of docs/cts-map.md for one list: the totals (groups and
// tests fully, partly and not covered) and one row per group.
std::string ctsListSection(const CtsList& list, const CtsCounts& counts);

// The markers around a list's generated part.
std::string ctsSectionBegin(const CtsList& list);
std::string ctsSectionEnd(const CtsList& list);

// `doc` with each list's part between its markers replaced by the generated
// one (sections[i] for lists[i]); an error names a marker the doc lacks.
Result<std::string> ctsMapDocument(const std::string& doc, const std::vector<CtsList>& lists,
                                   const std::vector<std::string>& sections);

}  // namespace rayspec
