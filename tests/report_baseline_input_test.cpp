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
  std::vector<NamePattern> p =
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
  std::vector<NamePattern> p =
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
  std::vector<NamePattern> p =
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

}  // namespace
}  // namespace rayspec
