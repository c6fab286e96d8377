// Shards of a run (run/shard.h).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <set>

#include "run/shard.h"

namespace rayspec {
namespace {

TEST(Shard, ParsesIOfNAndRefusesTheRest) {
  std::string error;
  const auto s = parseShard("2/4", &error);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->index, 1u);
  EXPECT_EQ(s->count, 4u);
  EXPECT_EQ(s->describe(), "shard 2 of 4");
  for (const char* bad : {"0/4", "5/4", "2", "a/b", "2/0", "-1/3", ""}) {
    error.clear();
    EXPECT_FALSE(parseShard(bad, &error)) << bad;
    EXPECT_NE(error.find("I/N"), std::string::npos) << bad;
  }
}

TEST(Shard, EveryCaseInExactlyOneShard) {
  for (size_t total : {0u, 1u, 7u, 370u})
    for (unsigned n : {1u, 2u, 3u, 16u}) {
      std::multiset<size_t> seen;
      for (unsigned i = 0; i < n; ++i)
        for (size_t p : shardPositions(total, Shard{i, n})) seen.insert(p);
      EXPECT_EQ(seen.size(), total);
      for (size_t p = 0; p < total; ++p)
        EXPECT_EQ(seen.count(p), 1u) << total << " " << n << " " << p;
    }
}

TEST(Shard, GoogleTestVariablesCountFromZeroAndTouchTheStatusFile) {
  const std::string status = testing::TempDir() + "/shard-status";
  std::filesystem::remove(status);
  setenv("GTEST_TOTAL_SHARDS", "3", 1);
  setenv("GTEST_SHARD_INDEX", "2", 1);
  setenv("GTEST_SHARD_STATUS_FILE", status.c_str(), 1);
  std::string error;
  const auto s = shardFromEnvironment(&error);
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->index, 2u);
  EXPECT_EQ(s->count, 3u);
  EXPECT_TRUE(std::filesystem::exists(status));
  setenv("GTEST_SHARD_INDEX", "3", 1);
  EXPECT_FALSE(shardFromEnvironment(&error));
  EXPECT_NE(error.find("GTEST_SHARD_INDEX=3"), std::string::npos) << error;
  unsetenv("GTEST_TOTAL_SHARDS");
  unsetenv("GTEST_SHARD_INDEX");
  unsetenv("GTEST_SHARD_STATUS_FILE");
  error.clear();
  EXPECT_FALSE(shardFromEnvironment(&error));
  EXPECT_EQ(error, "");
}

// GitLab CI's parallel jobs: CI_NODE_INDEX counts from 1; GoogleTest's
// variables, when set too, win.
TEST(Shard, GitLabVariablesCountFromOne) {
  setenv("CI_NODE_TOTAL", "4", 1);
  setenv("CI_NODE_INDEX", "4", 1);
  std::string error;
  auto s = shardFromEnvironment(&error);
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->index, 3u);
  EXPECT_EQ(s->count, 4u);
  setenv("CI_NODE_INDEX", "0", 1);
  EXPECT_FALSE(shardFromEnvironment(&error));
  EXPECT_NE(error.find("CI_NODE_INDEX=0"), std::string::npos) << error;
  error.clear();
  setenv("GTEST_TOTAL_SHARDS", "2", 1);
  setenv("GTEST_SHARD_INDEX", "0", 1);
  s = shardFromEnvironment(&error);
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->count, 2u);
  for (const char* v :
       {"CI_NODE_TOTAL", "CI_NODE_INDEX", "GTEST_TOTAL_SHARDS", "GTEST_SHARD_INDEX"})
    unsetenv(v);
}

}  // namespace
}  // namespace rayspec
