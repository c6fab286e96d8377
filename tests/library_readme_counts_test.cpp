// What the documentation says of the whole library is current or dated:
// every "N cases" with N of a library's size (100 or more) in README.md,
// docs/*.md and the measurements of references/runs/*.md either is the
// number of cases in cases/ now, or sits in a paragraph that names its date
// (or follows one that does, as a table follows its lead-in). A measurement
// of an older library keeps its date; a figure that reads as current cannot
// go stale.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "suite_cases.h"

namespace rayspec {
namespace {

// README.md, then the markdown pages of docs/ and references/runs/, sorted.
std::vector<std::string> documentationPages() {
  std::vector<std::string> pages{RAYSPEC_SOURCE_DIR "/README.md"};
  for (const char* dir : {RAYSPEC_SOURCE_DIR "/docs", RAYSPEC_SOURCE_DIR "/references/runs"}) {
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == ".md") found.push_back(entry.path().string());
    std::sort(found.begin(), found.end());
    pages.insert(pages.end(), found.begin(), found.end());
  }
  return pages;
}

std::vector<std::string> paragraphsOf(const std::string& page) {
  std::ifstream in(page);
  std::vector<std::string> paragraphs(1);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(' ') == std::string::npos) {
      if (!paragraphs.back().empty()) paragraphs.emplace_back();
      continue;
    }
    paragraphs.back() += line + "\n";
  }
  return paragraphs;
}

bool namesADate(const std::string& text) {  // YYYY-MM-DD
  for (size_t i = 0; i + 10 <= text.size(); ++i) {
    const std::string d = text.substr(i, 10);
    bool date = d[4] == '-' && d[7] == '-';
    for (size_t k : {0, 1, 2, 3, 5, 6, 8, 9}) date = date && std::isdigit((unsigned char)d[k]);
    if (date) return true;
  }
  return false;
}

struct CountClaim {
  long count = 0;
  std::string context;
};

// Every "N cases" in the text, but "up to N cases" (a limit, not a count).
std::vector<CountClaim> countClaims(const std::string& text) {
  std::vector<CountClaim> claims;
  for (size_t at = text.find(" cases"); at != std::string::npos; at = text.find(" cases", at + 1)) {
    size_t start = at;
    while (start > 0 && std::isdigit((unsigned char)text[start - 1])) --start;
    if (start == at) continue;
    if (start >= 6 && text.compare(start - 6, 6, "up to ") == 0) continue;
    const size_t from = start > 40 ? start - 40 : 0;
    claims.push_back({std::stol(text.substr(start, at - start)), text.substr(from, at + 6 - from)});
  }
  return claims;
}

TEST(ReadmeCounts, EveryWholeLibraryCountIsTodaysOrDated) {
  const long library = static_cast<long>(suiteCases().size());
  int checked = 0;
  for (const std::string& page : documentationPages()) {
    const std::vector<std::string> paragraphs = paragraphsOf(page);
    for (size_t i = 0; i < paragraphs.size(); ++i)
      for (const CountClaim& c : countClaims(paragraphs[i])) {
        if (c.count < 100) continue;  // a part of the library
        ++checked;
        const bool dated = namesADate(paragraphs[i]) || (i > 0 && namesADate(paragraphs[i - 1]));
        EXPECT_TRUE(c.count == library || dated)
            << page << ": \"..." << c.context << "\" is neither the library's " << library
            << " cases nor dated (YYYY-MM-DD in its paragraph or the one before)";
      }
  }
  EXPECT_GT(checked, 5) << "the documentation's case counts were not found";
}

TEST(ReadmeCounts, FindsCountsAndSkipsLimits) {
  const std::vector<CountClaim> c = countClaims("all 497 cases pass; up to 1024 cases per sweep");
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].count, 497);
  EXPECT_TRUE(namesADate("measured 2026-11-25 here"));
  EXPECT_FALSE(namesADate("measured 2026-1-25 here"));
}

}  // namespace
}  // namespace rayspec
