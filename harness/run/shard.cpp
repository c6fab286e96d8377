#include "run/shard.h"

#include <cstdlib>
#include <fstream>
#include <regex>

namespace rayspec {

std::string Shard::describe() const {
  return "shard " + std::to_string(index + 1) + " of " + std::to_string(count);
}

std::optional<Shard> parseShard(const std::string& text, std::string* error) {
  static const std::regex form(R"(^\s*([0-9]{1,6})\s*/\s*([0-9]{1,6})\s*$)");
  std::smatch m;
  if (std::regex_match(text, m, form)) {
    const unsigned i = std::stoul(m[1]), n = std::stoul(m[2]);
    if (i >= 1 && i <= n) return Shard{i - 1, n};
  }
  *error = "--shard expects I/N with 1 <= I <= N (e.g. 2/4), got '" + text + "'";
  return std::nullopt;
}

namespace {

// GitLab CI's parallel jobs: CI_NODE_INDEX counts from 1 to CI_NODE_TOTAL.
std::optional<Shard> gitlabShard(std::string* error) {
  const char* total = std::getenv("CI_NODE_TOTAL");
  const char* index = std::getenv("CI_NODE_INDEX");
  if (!total || !index) return std::nullopt;
  static const std::regex number(R"(^[0-9]{1,6}$)");
  if (std::regex_match(total, number) && std::regex_match(index, number)) {
    const unsigned n = std::stoul(total), i = std::stoul(index);
    if (n >= 1 && i >= 1 && i <= n) return Shard{i - 1, n};
  }
  *error = std::string("CI_NODE_INDEX=") + index + " and CI_NODE_TOTAL=" + total +
           " do not name a shard (the index counts from 1 to the total)";
  return std::nullopt;
}

}  // namespace

std::optional<Shard> shardFromEnvironment(std::string* error) {
  if (std::getenv("CI_NODE_TOTAL") && std::getenv("CI_NODE_INDEX") && !std::getenv("GTEST_TOTAL_SHARDS"))
    return gitlabShard(error);
  const char* total = std::getenv("GTEST_TOTAL_SHARDS");
  const char* index = std::getenv("GTEST_SHARD_INDEX");
  if (!total || !index) return std::nullopt;
  static const std::regex number(R"(^[0-9]{1,6}$)");
  if (std::regex_match(total, number) && std::regex_match(index, number)) {
    const unsigned n = std::stoul(total), i = std::stoul(index);
    if (n >= 1 && i < n) {
      if (const char* status = std::getenv("GTEST_SHARD_STATUS_FILE")) std::ofstream{status};
      return Shard{i, n};
    }
  }
  *error = std::string("GTEST_SHARD_INDEX=") + index + " and GTEST_TOTAL_SHARDS=" + total +
           " do not name a shard (the index counts from 0 and is below the total)";
  return std::nullopt;
}

std::vector<size_t> shardPositions(size_t total, const Shard& shard) {
  std::vector<size_t> out;
  for (size_t i = shard.index; i < total; i += shard.count) out.push_back(i);
  return out;
}

}  // namespace rayspec
