// Issue 55, "A wrong driver passed": cases/ray-query/tie-two-instances has
// one ray whose two hits tie exactly (two instances of one triangle at one
// place, custom indices 5 and 6), so the model marks it ambiguous (t-tie).
// The device's record must still be one of the two legal answers as a whole:
// a custom index read as the instance id (0 or 1, neither answer's) and a
// raygen counter counted on the branch of the other answer must each Fail,
// and the device as it ran must Pass.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"

namespace {
namespace fs = std::filesystem;
using cli::caseArg;
using cli::fresh;
using cli::readDeqpCsv;
using cli::sh;
using cli::slurp;

const std::string kCase = "ray-query/tie-two-instances";

class QueryTie : public ::testing::Test {
 protected:
  // The case as the device runs it, once for every test.
  static void SetUpTestSuite() {
    saved_ = fresh("query-tie-saved");
    rc_ = sh(cli::kBin + " run --no-validation -j 1" + caseArg(kCase) + " --out " + saved_,
             saved_ + "/log.txt");
  }
  static std::string statusOf(const std::string& out) {
    const auto status = readDeqpCsv(out + "/results.csv");
    const auto it = status.find(kCase);
    return it == status.end() ? "missing" : it->second;
  }
  static std::string saved_;
  static int rc_;
};
std::string QueryTie::saved_;
int QueryTie::rc_ = -1;

TEST_F(QueryTie, TheDeviceAsItRanPasses) {
  EXPECT_EQ(rc_, 0) << slurp(saved_ + "/log.txt");
  EXPECT_EQ(statusOf(saved_), "Pass") << slurp(saved_ + "/log.txt");
  // The ray is a tie of the two instances, not a clear hit.
  const auto model = nlohmann::json::parse(slurp(saved_ + "/" + kCase + "/model/results.json"));
  ASSERT_EQ(model["ambiguous"].size(), 1u) << model.dump(1);
  EXPECT_EQ(model["ambiguous"][0]["reason"], "t-tie");
  EXPECT_EQ(model["ambiguous"][0]["candidates"].size(), 2u);
}

TEST_F(QueryTie, ACustomIndexThatNeitherAnswerHasFails) {
  const std::string out = fresh("query-tie-custom-index");
  EXPECT_EQ(sh(cli::kBin +
                   " run --no-validation -j 1 --plant-fault "
                   "query-custom-index-is-instance-id" +
                   caseArg(kCase) + " --out " + out,
               out + "/log.txt"),
            1)
      << slurp(out + "/log.txt");
  EXPECT_EQ(statusOf(out), "Fail") << slurp(out + "/log.txt");
}

TEST_F(QueryTie, ACounterOnTheOtherAnswersBranchFails) {
  const std::string edited = fresh("query-tie-edited");
  fs::create_directories(fs::path(edited + "/" + kCase).parent_path());
  fs::copy(saved_ + "/" + kCase, edited + "/" + kCase, fs::copy_options::recursive);
  const std::string path = edited + "/" + kCase + "/device/results.json";
  auto results = nlohmann::json::parse(slurp(path));
  ASSERT_TRUE(results["counters"].contains("first")) << results.dump(1);
  // The records keep the answers the device took; one count of ray 0 moves
  // to the other answer's branch (ray 1, clear, counts `second` either way).
  const uint64_t first = results["counters"]["first"], second = results["counters"]["second"];
  ASSERT_EQ(first + second, 2u) << results.dump(1);
  const bool took_first = first == 1;
  results["counters"]["first"] = took_first ? 0u : 1u;
  results["counters"]["second"] = took_first ? 2u : 0u;
  std::ofstream(path) << results.dump(1);
  const std::string out = fresh("query-tie-counter");
  EXPECT_EQ(sh(cli::kBin + " run --no-validation -j 1 --device-results " + edited + caseArg(kCase) +
                   " --out " + out,
               out + "/log.txt"),
            1)
      << slurp(out + "/log.txt");
  EXPECT_EQ(statusOf(out), "Fail") << slurp(out + "/log.txt");
}

}  // namespace
