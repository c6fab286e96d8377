// Shards of a run (run/shard.h).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <set>

#include "run/shard.h"

namespace rayspec {
namespace {

TEST(Shard, ParsesIOfNAndRefusesTheRest) {
  const Result<Shard> s = parseShard("2/4");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->index, 1u);
  EXPECT_EQ(s->count, 4u);
  EXPECT_EQ(s->describe(), "shard 2 of 4");
  // No regular expression runs on the text: 50,000 leading spaces are an
  // error, not a stack overflow (issue 44), and, as in every other number
  // an option takes, no space is skipped (issue 56).
  const std::string spaces(100000, ' ');
  for (const std::string& bad :
       {std::string("0/4"), std::string("5/4"), std::string("2"), std::string("a/b"),
        std::string("2/0"), std::string("-1/3"), std::string(""), std::string("1234567/9999999"),
        std::string("1/2/3"), spaces + "1/x", spaces + "1/2", std::string("  3 /  4 "),
        std::string("1/2 "), std::string("+1/2"), std::string("0x1/2")}) {
    const Result<Shard> r = parseShard(bad);
    ASSERT_FALSE(r) << bad.substr(0, 40);
    EXPECT_NE(r.error().message.find("I/N"), std::string::npos) << bad.substr(0, 40);
    EXPECT_LT(r.error().message.size(), 300u);
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
  const auto s = shardFromEnvironment();
  ASSERT_TRUE(s && *s);
  EXPECT_EQ((*s)->index, 2u);
  EXPECT_EQ((*s)->count, 3u);
  EXPECT_TRUE(std::filesystem::exists(status));
  setenv("GTEST_SHARD_INDEX", "3", 1);
  const auto bad = shardFromEnvironment();
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("GTEST_SHARD_INDEX=3"), std::string::npos);
  unsetenv("GTEST_TOTAL_SHARDS");
  unsetenv("GTEST_SHARD_INDEX");
  unsetenv("GTEST_SHARD_STATUS_FILE");
  const auto none = shardFromEnvironment();
  ASSERT_TRUE(none) << "no variables: no shard, and no error";
  EXPECT_FALSE(*none);
}

// GitLab CI's parallel jobs: CI_NODE_INDEX counts from 1; GoogleTest's
// variables, when set too, win.
TEST(Shard, GitLabVariablesCountFromOne) {
  setenv("CI_NODE_TOTAL", "4", 1);
  setenv("CI_NODE_INDEX", "4", 1);
  auto s = shardFromEnvironment();
  ASSERT_TRUE(s && *s);
  EXPECT_EQ((*s)->index, 3u);
  EXPECT_EQ((*s)->count, 4u);
  setenv("CI_NODE_INDEX", "0", 1);
  const auto bad = shardFromEnvironment();
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("CI_NODE_INDEX=0"), std::string::npos);
  setenv("GTEST_TOTAL_SHARDS", "2", 1);
  setenv("GTEST_SHARD_INDEX", "0", 1);
  s = shardFromEnvironment();
  ASSERT_TRUE(s && *s);
  EXPECT_EQ((*s)->count, 2u);
  for (const char* v :
       {"CI_NODE_TOTAL", "CI_NODE_INDEX", "GTEST_TOTAL_SHARDS", "GTEST_SHARD_INDEX"})
    unsetenv(v);
}

}  // namespace
}  // namespace rayspec
