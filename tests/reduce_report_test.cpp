// reduce/reduce_report.h: report.md holds the reproduction and the reduced
// case as they are, whatever they hold: a run of backticks in a path (shown
// in the command, quoted for sh) does not end their code blocks.
#include <gtest/gtest.h>

#include <filesystem>

#include "read_text.h"
#include "reduce/reduce_report.h"
#include "test_dir.h"

namespace rayspec {
namespace {

// The text of the fenced code block that follows `heading` in markdown.
std::string blockAfter(const std::string& markdown, const std::string& heading) {
  const size_t at = markdown.find(heading);
  if (at == std::string::npos) return "(no " + heading + ")";
  const size_t fence_begin = markdown.find('`', at);
  const size_t fence_end = markdown.find_first_not_of('`', fence_begin);
  const std::string fence = markdown.substr(fence_begin, fence_end - fence_begin);
  const size_t begin = markdown.find('\n', fence_end) + 1;
  const size_t end = markdown.find("\n" + fence + "\n", begin);
  return end == std::string::npos ? "(unclosed)" : markdown.substr(begin, end - begin);
}

TEST(ReduceReport, CodeBlocksHoldTheirTextWhateverItHolds) {
  ReductionRecord r;
  r.case_name = "fam/case";
  r.command = "rayspec run --case '/tmp/a\n```\n# Injected\n```\nb/reduced.yaml'";
  r.reduced_text = "# Made by rayspec reduce; shown by: x\n```\n# Injected\n```\nrules: [R-X]\n";
  const std::string dir = testing_support::testDir();
  ASSERT_EQ(writeReduction(r, dir), "");
  const std::string report = slurp(dir + "/report.md");
  EXPECT_EQ(blockAfter(report, "## Reproduce"), r.command) << report;
  EXPECT_EQ(blockAfter(report, "## The case") + "\n", r.reduced_text) << report;
  EXPECT_NE(report.find("## Failing rays"), std::string::npos) << report;
}

// repro.amber is written beside the report where the export made one, its
// run line in report.md; where it refused, no file (an earlier one removed)
// and the report says why.
TEST(ReduceReport, TheAmberScriptIsWrittenOrItsRefusalSaid) {
  ReductionRecord r;
  r.case_name = "fam/case";
  r.reduced_text = "rules: [R-X]\n";
  r.amber = "#!amber\nSET ENGINE_DATA fence_timeout_ms 1000\n";
  const std::string dir = testing_support::testDir();
  ASSERT_EQ(writeReduction(r, dir), "");
  EXPECT_EQ(slurp(dir + "/repro.amber"), r.amber);
  EXPECT_EQ(blockAfter(slurp(dir + "/report.md"), "## Without rayspec: repro.amber"),
            kAmberRunLine);
  r.amber.clear();
  r.amber_refused = "an Amber script cannot carry the planted fault offsets-ignored";
  ASSERT_EQ(writeReduction(r, dir), "");
  EXPECT_FALSE(std::filesystem::exists(dir + "/repro.amber"));
  EXPECT_NE(slurp(dir + "/report.md").find("No repro.amber: " + r.amber_refused), std::string::npos)
      << slurp(dir + "/report.md");
}

}  // namespace
}  // namespace rayspec
