// Splitting a run over machines: `rayspec run --shard I/N` runs every N-th
// case (in case-name order) starting at the I-th, so N runs with I = 1..N
// run each case exactly once, families spread over all of them. Without
// --shard, GoogleTest's variables do the same (GTEST_TOTAL_SHARDS,
// GTEST_SHARD_INDEX counted from 0), and GTEST_SHARD_STATUS_FILE is touched
// to say the run understood them; GitLab CI's parallel jobs' variables too
// (CI_NODE_INDEX counted from 1, CI_NODE_TOTAL), where GoogleTest's are not
// set. `rayspec merge` joins the results folders.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/result.h"

namespace rayspec {

struct Shard {
  unsigned index = 0;  // from 0
  unsigned count = 1;
  std::string describe() const;  // "shard 2 of 4"
};

// "I/N" with 1 <= I <= N, or the error that says it is not.
Result<Shard> parseShard(const std::string& text);

// GoogleTest's sharding variables, when both are set, else GitLab CI's;
// nullopt when neither pair is set, an error when they are malformed.
// Touches GTEST_SHARD_STATUS_FILE when it is set.
Result<std::optional<Shard>> shardFromEnvironment();

// The positions (into a list of `total` items) that belong to the shard.
std::vector<size_t> shardPositions(size_t total, const Shard& shard);

}  // namespace rayspec
