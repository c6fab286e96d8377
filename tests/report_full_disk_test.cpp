// The reports on a disk that fills up (issue 56): each is written whole or
// not at all, the copy that was there stays as it was, and the error names
// every report not written and why.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "file_size_limit.h"
#include "read_text.h"
#include "report/write_reports.h"
#include "temp_dir.h"

namespace rayspec {
namespace {

const char* const kReports[] = {"results.csv", "junit.xml",    "summary.json",
                                "summary.txt", "failures.csv", "report.html"};

std::vector<CaseOutcome> failingCases(size_t n) {
  std::vector<CaseOutcome> out;
  for (size_t i = 0; i < n; ++i) {
    CaseOutcome o;
    o.name = "fam/case-" + std::to_string(i);
    o.verdict.add({Status::Fail, "R-MISS", std::string(100, 'm'), {}, 0});
    o.deriveFromVerdict();
    out.push_back(o);
  }
  return out;
}

TEST(FullDisk, EveryReportNotWrittenKeepsItsCopyAndIsNamed) {
  const std::string dir = freshTempDir("full-disk/reports");
  RunInfo info;
  info.device = "dev";
  info.model_tier = "exact";
  ASSERT_TRUE(writeReports(failingCases(1), info, dir));
  std::map<std::string, std::string> was;
  for (const char* report : kReports) was[report] = slurp(dir + "/" + report);
  Result<void> written;
  {
    const FileSizeLimit full(1024);  // smaller than each report of 100 cases
    written = writeReports(failingCases(100), info, dir);
  }
  ASSERT_FALSE(written);
  EXPECT_EQ(written.error().kind, ErrorKind::Harness);
  const std::string error = written.error().format();
  for (const char* report : kReports) {
    EXPECT_NE(error.find(dir + "/" + report + ": cannot write: File too large"), std::string::npos)
        << error;
    EXPECT_EQ(slurp(dir + "/" + report), was[report]) << report;
  }
  size_t entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) entries += e.exists();
  EXPECT_EQ(entries, std::size(kReports)) << "no temporary file is left";
}

}  // namespace
}  // namespace rayspec
