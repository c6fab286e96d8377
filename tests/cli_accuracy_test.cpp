// `rayspec accuracy` as a program (ctest cli/accuracy): on small sets it
// writes accuracy.txt, accuracy.json and accuracy.png, the JSON with one row
// per set and source (each model tier, the device) holding every field; a
// second run without a device compares the first run's saved device bundles
// (--device-results) as another device's.
#include <nlohmann/json.hpp>

#include "cli_helpers.h"

namespace {

using cli::kBin;

const char* const kFields[] = {"set",
                               "source",
                               "kind",
                               "cases",
                               "launch_rays",
                               "rays",
                               "trace_seconds",
                               "ms_per_mray",
                               "disagreeing_rays",
                               "disagreeing_per_mray",
                               "leaks",
                               "double_hits",
                               "other_primitive",
                               "extra_hits",
                               "t_error_ulp"};
const char* const kTFields[] = {"rays", "median", "p99", "max", "histogram"};
const std::string kSets = " --ordinary 'anyhit/ignore-*' --hard 'watertight/*'";

// The row of one set and source; fails the test unless there is exactly one.
nlohmann::json rowOf(const nlohmann::json& report, const std::string& set,
                     const std::string& source) {
  nlohmann::json found;
  int n = 0;
  for (const nlohmann::json& r : report["rows"])
    if (r["set"] == set && r["source"] == source) {
      found = r;
      ++n;
    }
  EXPECT_EQ(n, 1) << set << " / " << source;
  return found;
}

void expectRow(const nlohmann::json& report, const std::string& set, const std::string& source) {
  const nlohmann::json r = rowOf(report, set, source);
  if (r.is_null()) return;
  for (const char* f : kFields) EXPECT_TRUE(r.contains(f)) << set << " / " << source << ": " << f;
  for (const char* f : kTFields)
    EXPECT_TRUE(r["t_error_ulp"].contains(f)) << set << " / " << source << ": " << f;
  EXPECT_GT(r["rays"].get<uint64_t>(), 0u) << set << " / " << source;
  EXPECT_GT(r["ms_per_mray"].get<double>(), 0.0) << set << " / " << source;
  if (source == "model exact") {
    EXPECT_EQ(r["disagreeing_rays"], 0u) << set << ": the exact tier against itself";
  }
}

TEST(Accuracy, WritesTheReportWithARowPerSetTierAndDevice) {
  const std::string out = cli::fresh("accuracy");
  ASSERT_EQ(cli::sh(kBin + " accuracy" + kSets + " --strict-validation --out " + out, out + ".log"),
            0)
      << cli::slurp(out + ".log");
  for (const char* f : {"accuracy.txt", "accuracy.json", "accuracy.png"})
    EXPECT_GT(std::filesystem::file_size(out + "/" + f), 0u) << f;
  const nlohmann::json report = nlohmann::json::parse(cli::slurp(out + "/accuracy.json"));
  EXPECT_EQ(report["rows"].size(), 8u);  // 2 sets x (3 tiers + llvmpipe)
  for (const std::string set : {"ordinary", "hard"})
    for (const std::string source : {"model fast", "model robust", "model exact", "llvmpipe"})
      expectRow(report, set, source);
  // lavapipe runs any-hit twice on rays of watertight/double-hit (its
  // baseline's QualityWarning): the report must see it.
  EXPECT_GT(rowOf(report, "hard", "llvmpipe")["double_hits"].get<uint64_t>(), 0u);
  const std::string table = cli::slurp(out + "/accuracy.txt");
  EXPECT_NE(table.find("ordinary cases"), std::string::npos) << table;
  EXPECT_NE(table.find("t error histogram"), std::string::npos) << table;

  // The saved device bundles, compared as another machine's.
  const std::string saved = cli::fresh("accuracy-saved");
  ASSERT_EQ(cli::sh(kBin + " accuracy" + kSets + " --no-device --device-results " + out +
                        "/runs/ordinary/exact --device-results " + out + "/runs/hard/exact --out " +
                        saved,
                    saved + ".log"),
            0)
      << cli::slurp(saved + ".log");
  const nlohmann::json again = nlohmann::json::parse(cli::slurp(saved + "/accuracy.json"));
  for (const std::string set : {"ordinary", "hard"}) {
    expectRow(again, set, "llvmpipe");
    EXPECT_EQ(rowOf(again, set, "llvmpipe")["kind"], "device");
  }
  EXPECT_EQ(rowOf(again, "hard", "llvmpipe")["double_hits"],
            rowOf(report, "hard", "llvmpipe")["double_hits"]);
}

TEST(Accuracy, NoCaseInEitherSetIsASetupError) {
  const std::string out = cli::fresh("accuracy-none");
  EXPECT_EQ(
      cli::sh(kBin + " accuracy --ordinary 'nothing/*' --hard 'none/*' --out " + out, out + ".log"),
      2)
      << cli::slurp(out + ".log");
}

}  // namespace
