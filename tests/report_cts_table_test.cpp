// The README's table of the Khronos CTS ray_tracing_pipeline groups ("Against
// the Khronos CTS"): every group once, the counts summing to the stated total,
// and every case glob it names matching cases of the suite, so the table
// cannot name a case that was renamed or removed.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "suite_cases.h"

namespace rayspec {
namespace {

struct GroupRow {
  std::string group;
  long tests = 0;
  std::vector<std::string> globs;
  std::string notes;
};

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line.substr(1));
  while (std::getline(in, cell, '|')) {
    const size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
    out.push_back(a == std::string::npos ? std::string() : cell.substr(a, b - a + 1));
  }
  return out;
}

std::vector<GroupRow> readmeRows() {
  std::ifstream in(RAYSPEC_SOURCE_DIR "/README.md");
  std::string line;
  bool inside = false;
  std::vector<GroupRow> rows;
  const std::regex glob("`([^`]+)`");
  while (std::getline(in, line)) {
    if (line.find("<!-- cts-groups: begin -->") != std::string::npos) inside = true;
    if (line.find("<!-- cts-groups: end -->") != std::string::npos) break;
    if (!inside || line.rfind("| ", 0) != 0 || line.rfind("| CTS group", 0) == 0) continue;
    const std::vector<std::string> c = cells(line);
    if (c.size() < 4) continue;
    GroupRow r{c[0], std::stol(c[1]), {}, c[3]};
    for (std::sregex_iterator m(c[2].begin(), c[2].end(), glob), end; m != end; ++m)
      r.globs.push_back((*m)[1]);
    rows.push_back(r);
  }
  return rows;
}

TEST(ReadmeCtsTable, EveryGroupOnceAndTheCountsSumToTheMustpassTotal) {
  const std::vector<GroupRow> rows = readmeRows();
  ASSERT_EQ(rows.size(), 34u) << "dEQP-VK.ray_tracing_pipeline has 34 groups";
  std::set<std::string> names;
  long total = 0;
  for (const GroupRow& r : rows) {
    EXPECT_TRUE(names.insert(r.group).second) << r.group << " twice";
    total += r.tests;
    EXPECT_TRUE(!r.globs.empty() || !r.notes.empty())
        << r.group << ": no case and no reason why not";
  }
  EXPECT_EQ(total, 19206);
}

// A folder a row's notes name in parentheses, e.g. "(builtins/launch-zero)":
// its cases exist and are among the row's globs, so the notes cannot place
// a capability in a folder that does not hold it.
TEST(ReadmeCtsTable, EveryFolderTheNotesNameIsAmongTheRowsCases) {
  const std::regex folder("\\(([a-z0-9-]+/[a-z0-9/*-]+)\\)");
  for (const GroupRow& r : readmeRows()) {
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

TEST(ReadmeCtsTable, EveryCaseGlobMatchesSuiteCases) {
  for (const GroupRow& r : readmeRows())
    for (const std::string& g : r.globs)
      EXPECT_FALSE(findCases(kSuiteCases, g).empty())
          << r.group << ": `" << g << "` matches no case of cases/";
}

}  // namespace
}  // namespace rayspec
