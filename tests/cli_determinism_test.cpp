// Determinism: two runs of the whole suite, one with four cases at once and
// one with one at a time, write the same results folders, byte for byte, once
// the timings (and the run's date) are taken out.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"

namespace {
namespace fs = std::filesystem;
using cli::fresh;
using cli::kBin;
using cli::sh;
using cli::slurp;

// Drops every key that holds a duration; "cost" is the per-step breakdown
// (all durations, and which steps ran depends on the SPIR-V cache).
void dropTimings(nlohmann::json& j) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end();) {
      const std::string& key = it.key();
      if (key == "seconds" || key.ends_with("_seconds") || key == "started" || key == "cost" ||
          key == "accounted")
        it = j.erase(it);
      else
        dropTimings(*it++);
    }
  } else if (j.is_array()) {
    for (auto& e : j) dropTimings(e);
  }
}

// A file's contents with its timings taken out (by kind of file).
std::string withoutTimings(const fs::path& p) {
  const std::string text = slurp(p.string());
  const std::string ext = p.extension().string();
  if (p.filename() == "cost.json") return "";  // the case's time, step by step: nothing else
  if (p.filename() == "outcomes.jsonl") {  // the journal: one line per case in the order they ended
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
      nlohmann::json j = nlohmann::json::parse(line);
      dropTimings(j);
      lines.push_back(j.dump());
    }
    std::sort(lines.begin(), lines.end());
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
  }
  if (ext == ".json") {
    nlohmann::json j = nlohmann::json::parse(text);
    dropTimings(j);
    return j.dump(1);
  }
  if (p.filename() == "results.csv")  // case,status,duration
    return std::regex_replace(text, std::regex(",[0-9.e+-]+\n"), ",\n");
  if (ext == ".xml") return std::regex_replace(text, std::regex("time=\"[^\"]*\""), "time=\"\"");
  if (ext == ".html" || ext == ".txt") {
    std::string t = text.substr(0, text.find("Where the time went:"));  // summary.txt's cost table
    t = std::regex_replace(t, std::regex("[0-9]{4}-[0-9]{2}-[0-9]{2} [0-9:]{8} UTC"), "DATE");
    return std::regex_replace(t, std::regex("[0-9.e+-]+ s\\b"), "S s");
  }
  return text;
}

std::set<std::string> filesUnder(const fs::path& root) {
  std::set<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file()) out.insert(fs::relative(e.path(), root).generic_string());
  return out;
}

// The whole suite, twice, into two fresh folders: cases four at once (in
// long-lived workers, dealt longest first), then one at a time.
TEST(Determinism, TwoRunsOfTheSuiteWriteTheSameResults) {
  const std::string a = fresh("determinism-a"), b = fresh("determinism-b");
  const std::string run = kBin + " run --strict-validation --baseline " RAYSPEC_SOURCE_DIR
                                 "/references/baselines/lavapipe.csv --out ";
  ASSERT_EQ(sh(run + a + " -j 4", a + ".log"), 0) << slurp(a + ".log");
  ASSERT_EQ(sh(run + b + " -j 1", b + ".log"), 0) << slurp(b + ".log");
  const std::set<std::string> files_a = filesUnder(a), files_b = filesUnder(b);
  ASSERT_EQ(files_a, files_b);
  EXPECT_GT(files_a.size(), 1000u) << "the suite's bundles are missing";
  int differing = 0;
  for (const std::string& f : files_a) {
    if (withoutTimings(fs::path(a) / f) == withoutTimings(fs::path(b) / f)) continue;
    if (++differing <= 10) ADD_FAILURE() << f << " differs between two runs";
  }
  EXPECT_EQ(differing, 0);
}

// The comparison above would notice a difference: a record changed.
TEST(Determinism, AnEditedRecordIsNoticed) {
  const fs::path dir = fresh("determinism-edit");
  fs::create_directories(dir);
  const fs::path json = dir / "results.json", csv = dir / "results.csv";
  std::ofstream(json) << R"({"seconds": 1.5, "counters": {"miss": 3}})";
  const std::string before = withoutTimings(json);
  std::ofstream(json) << R"({"seconds": 2.5, "counters": {"miss": 3}})";
  EXPECT_EQ(withoutTimings(json), before);
  std::ofstream(json) << R"({"seconds": 2.5, "counters": {"miss": 4}})";
  EXPECT_NE(withoutTimings(json), before);
  std::ofstream(csv) << "a/b,Pass,0.51\n";
  const std::string csv_before = withoutTimings(csv);
  std::ofstream(csv) << "a/b,Pass,0.7\n";
  EXPECT_EQ(withoutTimings(csv), csv_before);
  std::ofstream(csv) << "a/b,Fail,0.7\n";
  EXPECT_NE(withoutTimings(csv), csv_before);
}

}  // namespace
