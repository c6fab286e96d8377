// The order cases are dealt to workers (run/case_order.h): longest first by
// the last run's timings, cases never timed before all others.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "run/case_order.h"

namespace rayspec {
namespace {

TEST(CaseOrder, LongestFirstUntimedBeforeAll) {
  const std::vector<std::string> names{"a", "b", "c", "d", "e"};
  const std::map<std::string, double> seconds{{"a", 0.1}, {"b", 4.0}, {"d", 0.1}, {"e", 1.0}};
  EXPECT_EQ(longestFirst(names, seconds), (std::vector<size_t>{2, 1, 4, 0, 3}));
}

TEST(CaseOrder, TimingsKeptAcrossRunsAndBadCacheIgnored) {
  const std::string dir = ::testing::TempDir() + "/rayspec-case-order";
  std::filesystem::remove_all(dir);
  EXPECT_TRUE(loadCaseSeconds(dir).empty());
  saveCaseSeconds(dir, {{"x", 2.5}});
  saveCaseSeconds(dir, {{"y", 0.5}});
  const auto loaded = loadCaseSeconds(dir);
  EXPECT_EQ(loaded, (std::map<std::string, double>{{"x", 2.5}, {"y", 0.5}}));
  std::ofstream(dir + "/case-seconds.json") << "{not json";
  EXPECT_TRUE(loadCaseSeconds(dir).empty());
  std::ofstream(dir + "/case-seconds.json") << R"({"x": "slow", "y": 1})";
  EXPECT_EQ(loadCaseSeconds(dir), (std::map<std::string, double>{{"y", 1.0}}));
}

}  // namespace
}  // namespace rayspec
