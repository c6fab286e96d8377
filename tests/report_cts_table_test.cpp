// The tables of Khronos CTS groups in docs/cts-map.md, one
// for dEQP-VK.ray_tracing_pipeline and one for dEQP-VK.ray_query: every group
// once, each row's count equal to the count under references/cts/ (derived
// from the mustpass list, with its source), the counts summing to the
// mustpass total, and every case glob a row names matching cases of the
// suite, so a table cannot name a case that was renamed or removed. Both
// tables are read and checked by the same code, parameterized by their
// markers.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "suite_cases.h"

namespace rayspec {
namespace {

// One table: where it sits in docs/cts-map.md, and what the mustpass list says.
struct CtsTable {
  const char* name;         // the gtest parameter name
  const char* begin;        // the marker line before the table
  const char* end;          // the marker line after it
  const char* counts_file;  // `uniq -c` output of the list's groups, under the source dir
  size_t groups;            // groups in the mustpass list
  long total;               // tests in the mustpass list
};

const CtsTable kCtsTables[] = {
    {"ray_tracing_pipeline", "<!-- cts-groups: begin -->", "<!-- cts-groups: end -->",
     "references/cts/ray-tracing-pipeline-groups.txt", 34, 19206},
    {"ray_query", "<!-- cts-ray-query-groups: begin -->", "<!-- cts-ray-query-groups: end -->",
     "references/cts/ray-query-groups.txt", 17, 27244},
};

// gtest names a failing parameter by this instead of its bytes.
void PrintTo(const CtsTable& table, std::ostream* out) {
  *out << table.name;
}

struct CtsGroupRow {
  std::string group;
  long tests = 0;
  std::vector<std::string> globs;
  std::string notes;
};

std::vector<std::string> ctsRowCells(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line.substr(1));
  while (std::getline(in, cell, '|')) {
    const size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
    out.push_back(a == std::string::npos ? std::string() : cell.substr(a, b - a + 1));
  }
  return out;
}

// The rows between the table's markers; a table whose markers are missing
// reads as no rows, which the group count then reports.
std::vector<CtsGroupRow> readCtsTableRows(const CtsTable& table) {
  std::ifstream in(RAYSPEC_SOURCE_DIR "/docs/cts-map.md");
  std::string line;
  bool inside = false;
  std::vector<CtsGroupRow> rows;
  const std::regex glob("`([^`]+)`");
  while (std::getline(in, line)) {
    if (line.find(table.begin) != std::string::npos) inside = true;
    if (line.find(table.end) != std::string::npos) break;
    if (!inside || line.rfind("| ", 0) != 0 || line.rfind("| CTS group", 0) == 0) continue;
    const std::vector<std::string> c = ctsRowCells(line);
    if (c.size() < 4) continue;
    CtsGroupRow r{c[0], std::stol(c[1]), {}, c[3]};
    for (std::sregex_iterator m(c[2].begin(), c[2].end(), glob), end; m != end; ++m)
      r.globs.push_back((*m)[1]);
    rows.push_back(r);
  }
  return rows;
}

// The counts file: "  COUNT GROUP" lines as `uniq -c` writes them, after
// '#' comments; the closing "COUNT total" line is the list's length.
std::map<std::string, long> readCtsGroupCounts(const CtsTable& table) {
  std::ifstream in(std::string(RAYSPEC_SOURCE_DIR "/") + table.counts_file);
  std::map<std::string, long> counts;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    long n = 0;
    std::string group;
    if (fields >> n >> group) counts[group] = n;
  }
  return counts;
}

class CtsMapTable : public testing::TestWithParam<CtsTable> {};

TEST_P(CtsMapTable, EveryGroupOnceAndTheCountsSumToTheMustpassTotal) {
  const CtsTable& table = GetParam();
  const std::vector<CtsGroupRow> rows = readCtsTableRows(table);
  ASSERT_EQ(rows.size(), table.groups) << table.name << " has " << table.groups << " groups";
  std::set<std::string> names;
  long total = 0;
  for (const CtsGroupRow& r : rows) {
    EXPECT_TRUE(names.insert(r.group).second) << r.group << " twice";
    total += r.tests;
    EXPECT_TRUE(!r.globs.empty() || !r.notes.empty())
        << r.group << ": no case and no reason why not";
  }
  EXPECT_EQ(total, table.total) << table.name << ": the rows' counts against the mustpass total";
}

// Each row's count is the one counted from the mustpass list, and the file
// itself holds the groups and the total the table is checked against.
TEST_P(CtsMapTable, EveryCountIsTheMustpassListsCount) {
  const CtsTable& table = GetParam();
  std::map<std::string, long> counted = readCtsGroupCounts(table);
  ASSERT_EQ(counted.count("total"), 1u) << table.counts_file << ": no total line";
  EXPECT_EQ(counted["total"], table.total) << table.counts_file;
  counted.erase("total");
  long sum = 0;
  for (const auto& [group, n] : counted) sum += n;
  EXPECT_EQ(counted.size(), table.groups) << table.counts_file;
  EXPECT_EQ(sum, table.total) << table.counts_file << ": the groups do not sum to the total";
  for (const CtsGroupRow& r : readCtsTableRows(table)) {
    const auto it = counted.find(r.group);
    if (it == counted.end()) {
      ADD_FAILURE() << r.group << ": no such group in " << table.counts_file;
      continue;
    }
    EXPECT_EQ(r.tests, it->second)
        << r.group << ": docs/cts-map.md's count against " << table.counts_file;
  }
}

// A folder a row's notes name in parentheses, e.g. "(builtins/launch-zero)":
// its cases exist and are among the row's globs, so the notes cannot place
// a capability in a folder that does not hold it.
TEST_P(CtsMapTable, EveryFolderTheNotesNameIsAmongTheRowsCases) {
  const std::regex folder("\\(([a-z0-9-]+/[a-z0-9/*-]+)\\)");
  for (const CtsGroupRow& r : readCtsTableRows(GetParam())) {
    std::set<std::string> row_cases;
    for (const std::string& g : r.globs)
      for (const CaseFile& f : findCases(kSuiteCases, g)) row_cases.insert(f.name);
    for (std::sregex_iterator m(r.notes.begin(), r.notes.end(), folder), end; m != end; ++m) {
      std::string named = (*m)[1];
      if (named.back() != '*') named += "*";
      const std::vector<CaseFile> found = findCases(kSuiteCases, named);
      EXPECT_FALSE(found.empty()) << r.group << ": the notes name " << named << ", no case";
      bool listed = false;
      for (const CaseFile& f : found) listed = listed || row_cases.count(f.name);
      EXPECT_TRUE(listed) << r.group << ": the notes name " << named
                          << ", which none of the row's globs covers";
    }
  }
}

TEST_P(CtsMapTable, EveryCaseGlobMatchesSuiteCases) {
  for (const CtsGroupRow& r : readCtsTableRows(GetParam()))
    for (const std::string& g : r.globs)
      EXPECT_FALSE(findCases(kSuiteCases, g).empty())
          << r.group << ": `" << g << "` matches no case of cases/";
}

INSTANTIATE_TEST_SUITE_P(CtsMap, CtsMapTable, testing::ValuesIn(kCtsTables),
                         [](const testing::TestParamInfo<CtsTable>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace rayspec
