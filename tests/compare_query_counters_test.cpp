// Counters and ray_query statements (compare/counter_modes.h): a count in a
// query's candidate block depends on the order and number of candidates
// offered, one in `after` or beside the query does not.
#include <gtest/gtest.h>

#include "compare/counter_modes.h"

namespace rayspec {
namespace {

Stmt countStmt(const std::string& name) {
  Stmt s;
  s.kind = Stmt::Kind::Count;
  s.counter = name;
  return s;
}

TEST(QueryCounterModes, CandidateBlockCountsAreInformational) {
  Case c;
  c.outputs.counters = {"offered", "boxes", "after", "before"};
  Stmt q;
  q.kind = Stmt::Kind::RayQuery;
  for (uint32_t k = 0; k < 2; ++k) {
    Stmt block;
    block.kind = Stmt::Kind::Candidates;
    block.size = k;
    block.then_ = {countStmt(k == 0 ? "offered" : "boxes")};
    q.then_.push_back(block);
  }
  q.else_ = {countStmt("after")};
  c.pipeline.raygen = {countStmt("before"), q};
  const auto modes = counterModes(c);
  EXPECT_EQ(modes.at("offered"), CounterMode::Informational);
  EXPECT_EQ(modes.at("boxes"), CounterMode::Informational);
  EXPECT_EQ(modes.at("after"), CounterMode::Exact);
  EXPECT_EQ(modes.at("before"), CounterMode::Exact);
  // A query may make the ray undefined (generate outside its interval): a
  // count after it may move on such a ray, one before it may not.
  const auto moved = countersUndefinedRaysMayMove(c);
  EXPECT_TRUE(moved.count("after"));
  EXPECT_FALSE(moved.count("before"));
}

}  // namespace
}  // namespace rayspec
