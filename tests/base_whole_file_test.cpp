// Whole files (base/whole_file.h): read within a size limit, written whole
// or not at all.
#include <gtest/gtest.h>

#include <filesystem>

#include "base/whole_file.h"
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

}  // namespace
}  // namespace rayspec
