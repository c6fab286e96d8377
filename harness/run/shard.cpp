#include "run/shard.h"

#include <cstdlib>
#include <fstream>
#include <regex>

namespace rayspec {

std::string Shard::describe() const {
  return "shard " + std::to_string(index + 1) + " of " + std::to_string(count);
}

Result<Shard> parseShard(const std::string& text) {
  static const std::regex form(R"(^\s*([0-9]{1,6})\s*/\s*([0-9]{1,6})\s*$)");
  std::smatch m;
  if (std::regex_match(text, m, form)) {
    const unsigned i = std::stoul(m[1]), n = std::stoul(m[2]);
    if (i >= 1 && i <= n) return Shard{i - 1, n};
  }
  return errorMessage("--shard expects I/N with 1 <= I <= N (e.g. 2/4), got '" + text + "'");
}

namespace {

// A CI engine's pair of variables: the shard's index, counted from `first`,
// and the number of shards. nullopt when either is unset; an error when they
// name no shard.
Result<std::optional<Shard>> shardFromVariables(const char* index_name, const char* total_name,
                                                unsigned first) {
  const char* total = std::getenv(total_name);
  const char* index = std::getenv(index_name);
  if (!total || !index) return std::optional<Shard>();
  static const std::regex number(R"(^[0-9]{1,6}$)");
  if (std::regex_match(total, number) && std::regex_match(index, number)) {
    const unsigned n = std::stoul(total), i = std::stoul(index);
    if (n >= 1 && i >= first && i - first < n) return std::optional<Shard>(Shard{i - first, n});
  }
  return errorMessage(std::string(index_name) + "=" + index + " and " + total_name + "=" + total +
                      " do not name a shard (the index counts from " + std::to_string(first) +
                      (first ? " to" : " and is below") + " the total)");
}

}  // namespace

Result<std::optional<Shard>> shardFromEnvironment() {
  if (std::getenv("GTEST_TOTAL_SHARDS") || std::getenv("GTEST_SHARD_INDEX")) {
    Result<std::optional<Shard>> s =
        shardFromVariables("GTEST_SHARD_INDEX", "GTEST_TOTAL_SHARDS", 0);
    if (const char* status = std::getenv("GTEST_SHARD_STATUS_FILE"); s && *s && status)
      std::ofstream{status};
    return s;
  }
  // GitLab CI's parallel jobs: CI_NODE_INDEX counts from 1 to CI_NODE_TOTAL.
  return shardFromVariables("CI_NODE_INDEX", "CI_NODE_TOTAL", 1);
}

std::vector<size_t> shardPositions(size_t total, const Shard& shard) {
  std::vector<size_t> out;
  for (size_t i = shard.index; i < total; i += shard.count) out.push_back(i);
  return out;
}

}  // namespace rayspec
