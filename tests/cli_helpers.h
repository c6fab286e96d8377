// Shared by the tests that run the rayspec command line as a program.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace cli {

inline const std::string kCases = RAYSPEC_SOURCE_DIR "/cases/";
inline const std::string kBin = RAYSPEC_BIN;

inline std::string caseArg(const std::string& name) {
  return " --case " + kCases + name + ".yaml";
}

// Runs a shell command; its output goes to log. Returns the exit status.
// GoogleTest's sharding variables (set when this test program is sharded)
// are not passed on: rayspec run would shard itself by them.
inline int sh(const std::string& command, const std::string& log) {
  const int s =
      std::system(("unset GTEST_TOTAL_SHARDS GTEST_SHARD_INDEX GTEST_SHARD_STATUS_FILE; " +
                   command + " > " + log + " 2>&1")
                      .c_str());
  return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A folder outside every run folder, with a marker file keep.txt ("keep"),
// that must survive whatever a test does to the runs beside it.
inline std::string victim(const std::string& root, const std::string& name) {
  const std::string dir = root + "/" + name;
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/keep.txt") << "keep";
  return dir;
}

// An empty folder for one test under the build's test output.
inline std::string fresh(const std::string& name) {
  const std::string dir = std::string(RAYSPEC_TEST_OUT) + "/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// results.csv as deqp-runner reads it: name,Status,duration per line, no header.
inline std::map<std::string, std::string> readDeqpCsv(const std::string& path) {
  std::map<std::string, std::string> status;
  const std::regex line(
      R"(^([^,\s]+),(Pass|Fail|Warn|Skip|Crash|Timeout|Flake|ExpectedFail|UnexpectedPass|UnexpectedImprovement\((?:Pass|Skip|Warn)\)|KnownFlake|Missing),([0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?)$)");
  std::ifstream in(path);
  std::string text;
  int n = 0;
  while (std::getline(in, text)) {
    ++n;
    std::smatch m;
    EXPECT_TRUE(std::regex_match(text, m, line))
        << path << ":" << n << ": not deqp-runner CSV: '" << text << "'";
    if (!m.empty()) status[m[1]] = m[2];
  }
  return status;
}

}  // namespace cli
