// Whole files (base/whole_file.h): read within a size limit, written whole
// or not at all.
#include <gtest/gtest.h>

#include <filesystem>

#include "base/whole_file.h"
#include "file_size_limit.h"
#include "read_text.h"
#include "result_support.h"
#include "temp_dir.h"

namespace rayspec {
namespace {

TEST(WholeFile, WritesAndReadsBack) {
  const std::string dir = freshTempDir("whole-file/round-trip");
  const std::string path = dir + "/text.txt";
  std::string error;
  ASSERT_TRUE(orError(writeWholeFile(path, std::string_view("one\ntwo\n")), &error)) << error;
  EXPECT_EQ(orError(readWholeFile(path, 8), &error), "one\ntwo\n");
  EXPECT_EQ(error, "");
  // Nothing but the file itself is left beside it.
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) files += entry.exists();
  EXPECT_EQ(files, 1u);
}

TEST(WholeFile, RefusesAFileOverItsLimit) {
  const std::string path = freshTempDir("whole-file/limit") + "/big.txt";
  std::string error;
  ASSERT_TRUE(orError(writeWholeFile(path, std::string_view("123456789")), &error)) << error;
  EXPECT_EQ(orError(readWholeFile(path, 8), &error), "");
  EXPECT_NE(error.find(path + ":0:0: 9 bytes, more than the 8"), std::string::npos) << error;
}

// A size that says nothing (a /proc file says 0) lets no more than the limit
// through: what is read is counted, not only what the size said.
TEST(WholeFile, ReadsNoMoreThanItsLimitWhateverTheSizeSaid) {
  std::string error;
  EXPECT_EQ(orError(readWholeFile("/proc/self/status", 16), &error), "");
  EXPECT_NE(error.find("more than the 16 bytes"), std::string::npos) << error;
  error.clear();
  EXPECT_NE(orError(readWholeFile("/proc/self/status", 1u << 20), &error).find("Name:"),
            std::string::npos)
      << error;
}

TEST(WholeFile, NamesTheFileItCannotReadOrWrite) {
  std::string error;
  orError(readWholeFile("/nonexistent/rayspec.txt", 100), &error);
  EXPECT_EQ(error, "/nonexistent/rayspec.txt:0:0: no such file");
  error.clear();
  EXPECT_FALSE(orError(writeWholeFile("/nonexistent-dir/x.txt", std::string_view("x")), &error));
  EXPECT_NE(error.find("/nonexistent-dir/x.txt: cannot write"), std::string::npos) << error;
  const std::string dir = freshTempDir("whole-file/folder");
  error.clear();
  orError(readWholeFile(dir, 100), &error);
  EXPECT_NE(error.find("no such file"), std::string::npos) << "a folder is no file: " << error;
}

// Issue 56: a write that fails part-way (a disk that fills up) leaves the
// copy that was there whole, and nothing beside it; the error names the file
// and why.
TEST(WholeFile, AWriteThatFailsLeavesTheFileThatWasThere) {
  const std::string dir = freshTempDir("whole-file/full");
  const std::string path = dir + "/summary.json";
  std::string error;
  ASSERT_TRUE(orError(writeWholeFile(path, std::string_view("{\"good\": true}\n")), &error))
      << error;
  {
    const FileSizeLimit full(4096);
    const Result<void> written = writeWholeFile(path, std::string(64 << 10, 'x'));
    ASSERT_FALSE(written);
    EXPECT_EQ(written.error().kind, ErrorKind::Harness);
    EXPECT_EQ(written.error().format(), path + ": cannot write: File too large");
  }
  EXPECT_EQ(slurp(path), "{\"good\": true}\n");
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) files += entry.exists();
  EXPECT_EQ(files, 1u) << "no temporary file is left";
}

// A folder where the file goes: the rename fails, the error says so, and the
// folder and what it holds stay.
TEST(WholeFile, AFolderInTheWayIsAnErrorNamingIt) {
  const std::string dir = freshTempDir("whole-file/in-the-way");
  const std::string path = dir + "/report.html";
  std::filesystem::create_directories(path + "/inside");
  const Result<void> written = writeWholeFile(path, std::string_view("<html></html>\n"));
  ASSERT_FALSE(written);
  EXPECT_EQ(written.error().format(), path + ": cannot write: Is a directory");
  EXPECT_TRUE(std::filesystem::is_directory(path + "/inside"));
  size_t entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) entries += entry.exists();
  EXPECT_EQ(entries, 1u) << "no temporary file is left";
}

}  // namespace
}  // namespace rayspec
