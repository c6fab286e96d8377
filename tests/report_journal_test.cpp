// The run's journal (report/case_journal.h): one outcome per line as cases
// end; a run killed mid-way is read back from it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "file_size_limit.h"
#include "read_text.h"
#include "report/case_journal.h"
#include "report/escape.h"
#include "report/outcome_json.h"
#include "report/write_reports.h"
#include "result_support.h"
#include "temp_dir.h"

namespace rayspec {
namespace {

CaseOutcome judgedOutcome(const std::string& name, Status s) {
  CaseOutcome o;
  o.name = name;
  o.verdict.add({s, "R-MISS", "said", {}, 0});
  o.status = o.verdict.status;
  o.headline = o.verdict.headline();
  return o;
}

std::string freshDir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/rayspec-journal/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(Journal, LastLineOfACaseWinsAndACutLineIsLeftOut) {
  const std::string dir = freshDir("cut");
  ASSERT_EQ(errorText(startJournal(dir)), "");
  ASSERT_EQ(errorText(appendJournal(judgedOutcome("f/a", Status::Fail), dir)), "");
  ASSERT_EQ(errorText(appendJournal(judgedOutcome("f/b", Status::Pass), dir)), "");
  ASSERT_EQ(errorText(appendJournal(judgedOutcome("f/a", Status::Pass), dir)),
            "");  // a resumed run judged it again
  std::ofstream(dir + "/" + kJournalFile, std::ios::app) << R"({"name": "f/c", "sta)";
  const auto journal = readJournal(dir);
  ASSERT_TRUE(journal) << journal.error().format();
  ASSERT_TRUE(*journal) << "the journal is there";
  const std::vector<CaseOutcome>& read = **journal;
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].name, "f/a");
  EXPECT_EQ(read[0].status, Status::Pass);
  EXPECT_EQ(read[1].name, "f/b");
}

// Issue 56: a run killed while it wrote a line leaves half of it; the next
// append (a resumed run's) cuts it off first, twice over, and the journal
// stays whole lines that read back.
TEST(Journal, AnAppendAfterALineCutShortCutsItOff) {
  const std::string dir = freshDir("resumed-after-cut");
  const std::string path = dir + "/" + kJournalFile;
  ASSERT_EQ(errorText(appendJournal(judgedOutcome("f/a", Status::Pass), dir)), "");
  const std::string whole = slurp(path);
  for (const char* name : {"f/b", "f/c"}) {
    std::ofstream(path, std::ios::app) << R"({"name": "f/x", "status": "Pa)";
    ASSERT_EQ(errorText(appendJournal(judgedOutcome(name, Status::Fail), dir)), "");
  }
  const std::string text = slurp(path);
  EXPECT_EQ(text.find("f/x"), std::string::npos) << text;
  EXPECT_EQ(text.substr(0, whole.size()), whole);
  const auto journal = readJournal(dir);
  ASSERT_TRUE(journal) << journal.error().format();
  ASSERT_EQ((*journal)->size(), 3u);
  EXPECT_EQ((**journal)[1].name, "f/b");
  EXPECT_EQ((**journal)[2].name, "f/c");
}

// An append the disk cannot take leaves no half line: the journal is as it
// was, and the error names it and why.
TEST(Journal, AnAppendThatFailsLeavesTheJournalAsItWas) {
  const std::string dir = freshDir("append-fails");
  const std::string path = dir + "/" + kJournalFile;
  ASSERT_EQ(errorText(appendJournal(judgedOutcome("f/a", Status::Pass), dir)), "");
  const std::string before = slurp(path);
  CaseOutcome big = judgedOutcome("f/b", Status::Fail);
  big.headline = std::string(64 << 10, 'h');
  {
    const FileSizeLimit full(before.size() + 4096);
    const Result<void> appended = appendJournal(big, dir);
    ASSERT_FALSE(appended);
    EXPECT_EQ(appended.error().kind, ErrorKind::Harness);
    EXPECT_EQ(appended.error().message, "cannot append to " + path + ": File too large");
  }
  EXPECT_EQ(slurp(path), before);
  ASSERT_EQ(errorText(appendJournal(judgedOutcome("f/c", Status::Pass), dir)), "");
  const auto journal = readJournal(dir);
  ASSERT_TRUE(journal) << journal.error().format();
  EXPECT_EQ((*journal)->size(), 2u);
}

// The journal and summary.json of a saved run are input: over their limits,
// each is refused, before it is read, by the error naming it.
TEST(Journal, AJournalOrSummaryOverItsLimitIsRefused) {
  const std::string dir = freshDir("huge");
  sparseFile(dir + "/" + kJournalFile, kMaxJournalBytes + 1);
  sparseFile(dir + "/summary.json", kMaxSummaryJsonBytes + 1);
  const auto journal = readJournal(dir);
  ASSERT_FALSE(journal);
  const std::string journal_error = journal.error().format();
  EXPECT_NE(journal_error.find(dir + "/" + kJournalFile + ": "), std::string::npos)
      << journal_error;
  EXPECT_NE(journal_error.find("more than the"), std::string::npos) << journal_error;
  const Result<SavedRun> summary = readSavedRun(dir);
  ASSERT_FALSE(summary);
  const std::string summary_error = summary.error().format();
  EXPECT_NE(summary_error.find(dir + "/summary.json: "), std::string::npos) << summary_error;
  EXPECT_NE(summary_error.find("more than the"), std::string::npos) << summary_error;
}

TEST(Journal, ABadLineInTheMiddleIsAnErrorNamingIt) {
  const std::string dir = freshDir("bad");
  ASSERT_EQ(errorText(appendJournal(judgedOutcome("f/a", Status::Pass), dir)), "");
  std::ofstream(dir + "/" + kJournalFile, std::ios::app) << "[1, 2]\n";
  ASSERT_EQ(errorText(appendJournal(judgedOutcome("f/b", Status::Pass), dir)), "");
  const auto journal = readJournal(dir);
  ASSERT_FALSE(journal);
  const std::string error = journal.error().format();
  EXPECT_NE(error.find(std::string(kJournalFile) + ":2:"), std::string::npos) << error;
  EXPECT_FALSE(*readJournal(freshDir("none"))) << "no journal: nothing, and no error";
}

// summary.json written at the start (no case, interrupted) and a journal of
// the cases that ended: the saved run is the journal's.
// A summary.json names each case's images, which become links in
// report.html: a name that climbs out is an error (issue 44).
TEST(Journal, AnImageNameThatClimbsIsRefused) {
  const std::string dir = freshDir("image-name");
  CaseOutcome o = judgedOutcome("family/a", Status::Pass);
  o.images = {"../../../../tmp/probe"};
  RunInfo info;
  info.device = "dev";
  info.model_tier = "exact";
  ASSERT_EQ(errorText(writeSummaryJson({o}, info, dir + "/summary.json")), "");
  const Result<SavedRun> saved = readSavedRun(dir);
  ASSERT_FALSE(saved);
  EXPECT_NE(saved.error().format().find("'images': '../../../../tmp/probe'"), std::string::npos)
      << saved.error().format();
}

// Control bytes in a saved message stay out of the XML (junit.xml,
// report.html): shown as \xNN.
TEST(Journal, ControlBytesNeverReachTheXml) {
  const std::string escaped = xmlEscape(std::string("bell\x07 esc\x1b nul") + '\0' + "<&>\xff");
  EXPECT_EQ(escaped, "bell\\x07 esc\\x1B nul\\x00&lt;&amp;&gt;\\xFF");
}

TEST(Journal, AnInterruptedRunIsReadFromItsJournal) {
  const std::string dir = freshDir("interrupted");
  RunInfo info;
  info.device = "dev";
  info.model_tier = "exact";
  info.planned_cases = 3;
  info.interrupted = true;
  ASSERT_EQ(errorText(writeReports({}, info, dir)), "");
  ASSERT_EQ(errorText(startJournal(dir)), "");
  ASSERT_EQ(errorText(appendJournal(judgedOutcome("f/a", Status::Pass), dir)), "");
  const Result<SavedRun> saved = readSavedRun(dir);
  ASSERT_TRUE(saved) << saved.error().format();
  ASSERT_EQ(saved->outcomes.size(), 1u);
  EXPECT_EQ(saved->outcomes[0].name, "f/a");
  // A finished run is its summary.json, whatever its journal holds.
  info.interrupted = false;
  ASSERT_EQ(errorText(writeReports({}, info, dir)), "");
  EXPECT_TRUE(readSavedRun(dir)->outcomes.empty());
}

// A case whose details JSON cannot hold: an Input error (the case is at
// fault, report/json_text.h), and the journal and summary.json stay as they were.
TEST(Journal, DetailsThatAreNotUtf8AreAnInputErrorAndNothingIsAppended) {
  const std::string dir = freshDir("utf8");
  ASSERT_EQ(errorText(appendJournal(judgedOutcome("f/a", Status::Pass), dir)), "");
  const Result<void> appended = appendJournal(judgedOutcome("f/\xfe", Status::Pass), dir);
  ASSERT_FALSE(appended);
  EXPECT_EQ(appended.error().kind, ErrorKind::Input);
  const auto journal = readJournal(dir);
  ASSERT_TRUE(journal) << journal.error().format();
  ASSERT_EQ((*journal)->size(), 1u);
  const Result<void> summary =
      writeSummaryJson({judgedOutcome("f/\xfe", Status::Pass)}, RunInfo{}, dir + "/summary.json");
  ASSERT_FALSE(summary);
  EXPECT_EQ(summary.error().kind, ErrorKind::Input);
  EXPECT_FALSE(std::filesystem::exists(dir + "/summary.json"));
}

// A file that cannot be written is the harness's error, naming the file.
TEST(Journal, AJournalThatCannotBeWrittenIsAHarnessError) {
  const Result<void> started = startJournal("/nonexistent-rayspec-dir");
  ASSERT_FALSE(started);
  EXPECT_EQ(started.error().kind, ErrorKind::Harness);
  EXPECT_EQ(started.error().message,
            "cannot write /nonexistent-rayspec-dir/outcomes.jsonl: No such file or directory");
}

}  // namespace
}  // namespace rayspec
