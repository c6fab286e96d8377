#include "run/shard.h"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <optional>

#include "base/visible_text.h"

namespace rayspec {

std::string Shard::describe() const {
  return "shard " + std::to_string(index + 1) + " of " + std::to_string(count);
}

namespace {

// 1 to 6 decimal digits from `at`, nothing else (no sign, no space: as
// every other number rayspec's options take); nullopt otherwise. A plain
// scanner: no regular expression runs on input text.
std::optional<unsigned> numberAt(const std::string& text, size_t& at) {
  const size_t start = at;
  unsigned v = 0;
  while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at])) && at - start < 7)
    v = v * 10 + static_cast<unsigned>(text[at++] - '0');
  const size_t digits = at - start;
  if (digits == 0 || digits > 6) return std::nullopt;
  return v;
}

// The whole of `text` is one number of 1 to 6 digits.
std::optional<unsigned> wholeNumber(const std::string& text) {
  size_t at = 0;
  const auto v = numberAt(text, at);
  return v && at == text.size() ? v : std::nullopt;
}

}  // namespace

Result<Shard> parseShard(const std::string& text) {
  size_t at = 0;
  const auto i = numberAt(text, at);
  const bool slash = i && at < text.size() && text[at] == '/';
  if (slash) ++at;
  const auto n = slash ? numberAt(text, at) : std::nullopt;
  if (n && at == text.size() && *i >= 1 && *i <= *n) return Shard{*i - 1, *n};
  return errorMessage("--shard expects I/N with 1 <= I <= N (e.g. 2/4), got '" +
                      visibleText(text, 80) + "'");
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
  const auto n = wholeNumber(total), i = wholeNumber(index);
  if (n && i && *n >= 1 && *i >= first && *i - first < *n)
    return std::optional<Shard>(Shard{*i - first, *n});
  return errorMessage(std::string(index_name) + "=" + visibleText(index, 80) + " and " +
                      total_name + "=" + visibleText(total, 80) +
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
