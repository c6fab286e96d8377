// Case files on disk: names from paths, bad and huge files, and every case of
// the suite parsing cleanly.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "parse/parse_case.h"
#include "parse_support.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

TEST(ParseCaseFile, NameFamilyAndBadFiles) {
  const std::string root = std::string(RAYSPEC_SOURCE_DIR) + "/tests/data";
  ParseResult r = parseCaseFile(root + "/bad/unknown-key.yaml", root);
  expectError(r, 8, "scene.instancess", "unknown key");
  EXPECT_EQ(r.errors.at(0).loc.file, root + "/bad/unknown-key.yaml");
  r = parseCaseFile(root + "/bad/ignore-in-closest-hit.yaml", root);
  expectError(r, 15, "pipeline.hit_groups[0].closest_hit[1]", "not allowed in closest_hit");
  r = parseCaseFile(root + "/bad/malformed.yaml", root);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_GE(r.errors[0].loc.line, 2);
  r = parseCaseFile(root + "/bad/does-not-exist.yaml", root);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].format(), root + "/bad/does-not-exist.yaml:0:0: no such file");
}

// A case file over kMaxCaseFileBytes is refused unread, naming the file.
TEST(ParseCaseFile, RefusesAHugeFile) {
  const std::string path = ::testing::TempDir() + "/rayspec-huge-case.yaml";
  { std::ofstream out(path); }
  std::filesystem::resize_file(path, kMaxCaseFileBytes + 1);  // sparse: nothing written
  const ParseResult r = parseCaseFile(path, "/");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].loc.file, path);
  EXPECT_NE(r.errors[0].message.find("more than the " + std::to_string(kMaxCaseFileBytes)),
            std::string::npos)
      << r.errors[0].message;
  std::filesystem::remove(path);
}

TEST(ParseCaseFile, NameIsPathUnderRoot) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "rayspec_case_test" / "anyhit";
  fs::create_directories(dir);
  const fs::path file = dir / "ignore-odd.yaml";
  {
    std::ofstream out(file);
    out << "rules: [R-IGNORE]\nrays: {list: [{origin: [0, 0, 1], direction: [0, 0, "
           "-1]}]}\npipeline: {miss: [[]]}\n";
  }
  ParseResult r = parseCaseFile(file.string(), dir.parent_path().string());
  ASSERT_TRUE(r.value) << allErrors(r);
  EXPECT_EQ(r.value->name, "anyhit/ignore-odd");
  EXPECT_EQ(r.value->family, "anyhit");
  EXPECT_EQ(r.value->file, file.string());
  fs::remove_all(dir.parent_path());
}

// Every case of the suite parses without errors.
TEST(Suite, AllCasesParse) {
  namespace fs = std::filesystem;
  int count = 0;
  for (const CaseFile& f : suiteCases()) {
    ++count;
    ParseResult r = loadSuiteCase(f);
    EXPECT_TRUE(r.value.has_value()) << allErrors(r);
    EXPECT_TRUE(r.errors.empty()) << f.name;
  }
  EXPECT_GT(count, 0) << "no cases in " << kSuiteCases;
}

}  // namespace
}  // namespace rayspec
