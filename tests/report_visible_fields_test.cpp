// Text from input in the line-oriented outputs (the console, summary.txt,
// results.csv, failures.csv): a case name from a file's name, a device's
// validation message, a saved headline holding escape sequences and a line
// break before a forged "::error" are shown by the visible-text rule
// (base/visible_text.h visibleLine), never obeyed by a terminal or a CI log.
#include <gtest/gtest.h>

#include <sstream>

#include "base/visible_text.h"
#include "hostile_text.h"
#include "read_text.h"
#include "report/baseline_gate.h"
#include "report/escape.h"
#include "report/run_summary.h"
#include "report/write_reports.h"
#include "test_dir.h"

namespace rayspec {
namespace {

using testing_support::kHostileText;
using testing_support::obeyedText;

// A failing case and a case error whose every field of text comes from input.
std::vector<CaseOutcome> hostileOutcomes() {
  std::vector<CaseOutcome> v(2);
  v[0].name = "fam/" + kHostileText + ",x";
  v[0].verdict.add(
      {Status::Fail, "R-VALIDATION", "1 validation-layer error(s); first: " + kHostileText, {}, 0});
  v[0].verdict.undefined.push_back({UndefinedReason::RayParameters, 1, {0}, kHostileText});
  v[0].deriveFromVerdict();
  v[0].baseline = BaselineMatch::Flake;
  v[0].baseline_note = kHostileText;
  v[1].name = kHostileText;
  v[1].verdict.add({Status::CaseError, "case-file", kHostileText, {}, 0});
  v[1].deriveFromVerdict();
  v[1].headline = kHostileText;  // as a saved summary.json may hold it
  return v;
}

TEST(VisibleFields, SummaryTextShowsInputAndObeysNone) {
  const std::string path = testing_support::testDir() + "/summary.txt";
  ASSERT_TRUE(writeSummaryText(hostileOutcomes(), RunInfo{}, path));
  const std::string text = slurp(path);
  EXPECT_EQ(obeyedText(text), "") << text;
  EXPECT_NE(text.find(visibleLine(kHostileText)), std::string::npos) << text;
}

TEST(VisibleFields, ResultsCsvHasOneQuotedLinePerCase) {
  const std::string dir = testing_support::testDir();
  const std::vector<CaseOutcome> outcomes = hostileOutcomes();
  ASSERT_TRUE(writeResultsCsv(outcomes, dir + "/results.csv"));
  ASSERT_TRUE(writeFailuresCsv(outcomes, "", dir + "/failures.csv"));
  for (const char* file : {"/results.csv", "/failures.csv"})
    EXPECT_EQ(obeyedText(slurp(dir + file)), "") << slurp(dir + file);
  std::istringstream lines(slurp(dir + "/results.csv"));
  std::vector<std::string> rows;
  for (std::string line; std::getline(lines, line);) rows.push_back(line);
  ASSERT_EQ(rows.size(), outcomes.size()) << slurp(dir + "/results.csv");
  // The first name holds a comma: quoted, and read back as the visible name.
  const std::string first = csvField(visibleLine(outcomes[0].name));
  EXPECT_EQ(first.front(), '"');
  EXPECT_EQ(rows[0].substr(0, first.size() + 1), first + ",") << rows[0];
  EXPECT_EQ(csvFieldText(first), visibleLine(outcomes[0].name));
}

TEST(VisibleFields, TheConsoleShowsInputAndObeysNone) {
  RunSummary summary(2);
  testing::internal::CaptureStdout();
  for (const CaseOutcome& o : hostileOutcomes()) summary.add(o);
  summary.addTeardownError(kHostileText);
  summary.print();
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(obeyedText(out), "") << out;
  EXPECT_NE(out.find(visibleLine(kHostileText)), std::string::npos) << out;
}

}  // namespace
}  // namespace rayspec
