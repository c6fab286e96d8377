// Determinism: the whole suite in one run, one case at a time, writes what
// the case/<family> tests wrote running it family by family (several cases at
// once in long-lived workers, dealt longest first), byte for byte once the
// timings (and the run's date) are taken out: every file of every case, and
// every case's line of results.csv and outcomes.jsonl.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
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
using cli::readDeqpCsv;
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

// A run folder's journal as case name -> its line without timings.
std::map<std::string, std::string> journalLines(const fs::path& run) {
  std::map<std::string, std::string> out;
  std::istringstream in(slurp((run / "outcomes.jsonl").string()));
  for (std::string line; std::getline(in, line);) {
    nlohmann::json j = nlohmann::json::parse(line);
    dropTimings(j);
    out[j["name"].get<std::string>()] = j.dump();
  }
  return out;
}

// Where the case/<family> test of a case wrote its run.
fs::path familyRun(const std::string& case_name) {
  return fs::path(RAYSPEC_FAMILY_RUNS) / case_name.substr(0, case_name.find('/'));
}

// The files of one case in run a and in its family's run.
int compareCase(const fs::path& a, const std::string& name) {
  const fs::path in_a = a / name, in_family = familyRun(name) / name;
  const std::set<std::string> files_a = filesUnder(in_a), files_family = filesUnder(in_family);
  if (files_a != files_family) {
    ADD_FAILURE() << name << ": the whole run and the family run wrote different files";
    return 1;
  }
  int differing = 0;
  for (const std::string& f : files_a)
    if (withoutTimings(in_a / f) != withoutTimings(in_family / f)) {
      if (++differing <= 3) ADD_FAILURE() << name << "/" << f << " differs from " << in_family;
    }
  return differing;
}

TEST(Determinism, TheSuiteInOneRunWritesWhatItsFamiliesWrite) {
  ASSERT_TRUE(fs::exists(RAYSPEC_FAMILY_RUNS))
      << RAYSPEC_FAMILY_RUNS << " is missing: the case/<family> tests write it (ctest runs them "
      << "first)";
  const std::string a = fresh("determinism-a");
  ASSERT_EQ(sh(kBin +
                   " run -j 1 --strict-validation --baseline " RAYSPEC_SOURCE_DIR
                   "/references/baselines/lavapipe.csv --out " +
                   a,
               a + ".log"),
            0)
      << slurp(a + ".log");
  const std::map<std::string, std::string> status = readDeqpCsv(a + "/results.csv");
  const std::map<std::string, std::string> journal = journalLines(a);
  ASSERT_GT(status.size(), 400u) << "the suite's cases are missing";
  EXPECT_EQ(journal.size(), status.size());
  int differing = 0;
  std::map<std::string, std::map<std::string, std::string>> family_status, family_journal;
  for (const auto& [name, st] : status) {
    const std::string family = familyRun(name).string();
    if (!family_status.count(family)) {
      family_status[family] = readDeqpCsv(family + "/results.csv");
      family_journal[family] = journalLines(family);
    }
    EXPECT_EQ(family_status[family][name], st) << name << ": results.csv";
    EXPECT_EQ(family_journal[family][name], journal.at(name)) << name << ": outcomes.jsonl";
    differing += compareCase(a, name);
  }
  EXPECT_EQ(differing, 0);
  size_t family_cases = 0;
  for (const auto& [family, rows] : family_status) family_cases += rows.size();
  EXPECT_EQ(family_cases, status.size()) << "the family runs hold cases the whole run has not";
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
