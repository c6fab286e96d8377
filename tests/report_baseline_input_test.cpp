// Baseline, flakes and skips files as untrusted input (issue 24): long lines,
// byte-order marks, patterns that backtrack catastrophically in a
// backtracking engine, entries listed twice and oversized files.
#include <gtest/gtest.h>

#include <fstream>

#include "report/baseline.h"
#include "result_support.h"
#include "test_dir.h"

namespace rayspec {
namespace {

std::string writeInput(const std::string& name, const std::string& text) {
  const std::string path = testing_support::testDir() + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// A 64 KiB comment and a 64 KiB malformed line: read line by line (std::regex
// recursed once per byte and overflowed the stack at about 50 KB).
TEST(BaselineInput, LongLinesAreReadNotRecursedInto) {
  std::string error;
  const std::string comment = "# " + std::string(64 << 10, 'x') + "\n";
  Baseline b =
      orError(loadBaseline(writeInput("long-comment.csv", comment + "fam/a,Fail\n")), &error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(b.expected.at("fam/a"), Status::Fail);
  orError(
      loadBaseline(writeInput("long-entry.csv", "fam/" + std::string(64 << 10, 'y') + ",Fail,\n")),
      &error);
  EXPECT_NE(error.find("long-entry.csv:1: expected 'case,Status'"), std::string::npos)
      << error.substr(0, 300);
  EXPECT_LT(error.size(), 1000u);  // the line is shown cut, with its length
  EXPECT_NE(error.find("bytes)"), std::string::npos);
  error.clear();
  NamePatterns p =
      orError(loadNamePatterns(writeInput("long-skips.txt", comment + "^fam/b$\n")), &error);
  EXPECT_EQ(error, "");
  ASSERT_EQ(p.size(), 1u);
}

// A UTF-8 byte-order mark before the first line is no part of it: the first
// entry and the first pattern count.
TEST(BaselineInput, AByteOrderMarkIsDropped) {
  std::string error;
  // "\xBF" and "fam" stay two literals: one would read \xBFfa as one escape.
  Baseline b = orError(loadBaseline(writeInput("bom.csv",
                                               "\xEF\xBB\xBF"
                                               "fam/a,Fail\r\nfam/b,Crash\r\n")),
                       &error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(b.expected.count("fam/a"), 1u);
  EXPECT_EQ(b.expected.at("fam/b"), Status::Crash);
  NamePatterns p =
      orError(loadNamePatterns(writeInput("bom-skips.txt", "\xEF\xBB\xBF^fam/a$\n")), &error);
  EXPECT_EQ(error, "");
  EXPECT_NE(findPattern(p, "fam/a"), nullptr);
  // A BOM anywhere else is shown, not hidden.
  orError(loadBaseline(writeInput("bom-later.csv",
                                  "fam/a,Fail\n\xEF\xBB\xBF"
                                  "fam/b,Fail\n")),
          &error);
  EXPECT_NE(error.find("bom-later.csv:2:"), std::string::npos) << error;
  EXPECT_NE(error.find("\\xEF\\xBB\\xBF"), std::string::npos) << error;
}

// Nested stars against a name that almost matches: exponential in a
// backtracking matcher (it ran for over 11 minutes), linear in RE2.
TEST(BaselineInput, NestedStarsMatchInLinearTime) {
  std::string error;
  NamePatterns p =
      orError(loadNamePatterns(writeInput("evil-skips.txt", "^(.*)*(.*)*(.*)*(.*)*Z$\n")), &error);
  ASSERT_EQ(error, "");
  EXPECT_EQ(findPattern(p, "abcdefghijklmnopqrstuvwxyz"), nullptr);
  EXPECT_NE(findPattern(p, "abcdefghijklmnopqrstuvwxyZ"), nullptr);
  // A back-reference is not RE2: an error naming the file and line.
  orError(loadNamePatterns(writeInput("backref-skips.txt", "# x\n(a)\\1\n")), &error);
  EXPECT_NE(error.find("backref-skips.txt:2: not a regular expression"), std::string::npos)
      << error;
}

TEST(BaselineInput, ACaseListedTwiceIsAnError) {
  std::string error;
  orError(loadBaseline(writeInput("twice.csv", "fam/a,Fail\nfam/b,Pass\n\"fam/a\",Crash\n")),
          &error);
  EXPECT_NE(error.find("twice.csv:3: fam/a is listed again (first on line 1)"), std::string::npos)
      << error;
}

// An entry no case of the library has (renamed or removed) would never apply:
// it is reported with its line.
TEST(BaselineInput, EntriesOfNoCaseAreReportedWithTheirLine) {
  std::string error;
  const Baseline b =
      orError(loadBaseline(writeInput("stale.csv", "# why\nfam/a,Fail\nfam/gone,Crash\n")), &error);
  ASSERT_EQ(error, "");
  const std::vector<std::string> unknown = unknownEntries(b, {"fam/a", "fam/b"});
  ASSERT_EQ(unknown.size(), 1u);
  EXPECT_NE(unknown[0].find("stale.csv:3: fam/gone is no case of the library"), std::string::npos)
      << unknown[0];
}

TEST(BaselineInput, AnOversizedFileIsRefusedWithItsSize) {
  std::string error;
  const std::string path = writeInput("huge.csv", std::string(kMaxBaselineBytes + 1, '#'));
  orError(loadBaseline(path), &error);
  EXPECT_NE(error.find("huge.csv: " + std::to_string(kMaxBaselineBytes + 1) + " bytes"),
            std::string::npos)
      << error;
}

// Issue 56: 60,000 patterns of x[a-z]{1000} (780 KB; each compiles to about
// a thousand RE2 instructions) took 3.1 GB. The patterns' compiled size is
// bounded as a whole: the file is refused at the line that passes the bound,
// long before its end, naming the file and that line.
TEST(BaselineInput, PatternsThatCompileLargeAreRefusedAtTheLine) {
  std::string text;
  for (int i = 0; i < 60000; ++i) text += "x[a-z]{1000}\n";
  std::string error;
  orError(loadNamePatterns(writeInput("large-skips.txt", text)), &error);
  const std::string at = "large-skips.txt:";
  const size_t found = error.find(at);
  ASSERT_NE(found, std::string::npos) << error;
  const int line = std::stoi(error.substr(found + at.size()));
  EXPECT_GT(line, 1);
  EXPECT_LE(line, kMaxPatternInstructions / 1000 + 1) << error;
  EXPECT_NE(error.find("the patterns up to this one compile to"), std::string::npos) << error;
  EXPECT_NE(error.find("more than the " + std::to_string(kMaxPatternInstructions)),
            std::string::npos)
      << error;
  // One pattern past the bound alone: refused at its line too.
  std::string one;
  for (int i = 0; i < 500; ++i) one += "x[a-z]{1000}";
  orError(loadNamePatterns(writeInput("one-large-skips.txt", "^fam/\n" + one + "\n")), &error);
  EXPECT_NE(error.find("one-large-skips.txt:2: '"), std::string::npos) << error.substr(0, 300);
  EXPECT_NE(error.find("this pattern alone compiles to more RE2 instructions"), std::string::npos)
      << error.substr(0, 300);
}

// Patterns that compile small but parse large (an empty group is 4 bytes and
// no instruction; RE2 keeps each parse until the set compiles, and its
// compiler crashed on 1 MiB of `|`): their text is bounded too, refused at
// the line that passes it.
TEST(BaselineInput, PatternsOfMuchTextAreRefusedAtTheLine) {
  std::string groups;
  for (int i = 0; i < 1000; ++i) groups += "(?:)";
  std::string text = "# 4000 bytes a line\n";
  for (int i = 0; i < 100; ++i) text += groups + "  # a comment does not count\n";
  std::string error;
  orError(loadNamePatterns(writeInput("much-text-skips.txt", text)), &error);
  EXPECT_NE(error.find("much-text-skips.txt:67: '(?:)"), std::string::npos) << error.substr(0, 300);
  EXPECT_NE(error.find("the patterns up to this one hold 264000 bytes, more than the " +
                       std::to_string(kMaxPatternBytes)),
            std::string::npos)
      << error;
}

// Many small patterns fit; the pattern found is the first in the file that
// matches, with its own line.
TEST(BaselineInput, ManySmallPatternsMatchInTheFilesOrder) {
  std::string text = "# small ones\n";
  for (int i = 0; i < 5000; ++i) text += "^fam/case" + std::to_string(i) + "$\n";
  text += "^fam/\n";
  std::string error;
  const NamePatterns p = orError(loadNamePatterns(writeInput("small-skips.txt", text)), &error);
  ASSERT_EQ(error, "");
  ASSERT_EQ(p.size(), 5001u);
  const NamePattern* hit = findPattern(p, "fam/case4321");
  ASSERT_NE(hit, nullptr);
  EXPECT_EQ(hit->text, "^fam/case4321$");
  EXPECT_EQ(hit->where, testing_support::testDir() + "/small-skips.txt:4323");
  hit = findPattern(p, "fam/other");
  ASSERT_NE(hit, nullptr);
  EXPECT_EQ(hit->text, "^fam/");
  EXPECT_EQ(findPattern(p, "other/case1"), nullptr);
  EXPECT_EQ(findPattern(NamePatterns{}, "fam/case1"), nullptr);
}

}  // namespace
}  // namespace rayspec
