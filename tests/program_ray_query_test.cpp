// The ray_query statement in the stage vocabulary (program/program.h): where
// its getters, confirm, generate and terminate_query may stand, and what
// its candidate blocks may hold.
#include <gtest/gtest.h>

#include "program/builtins.h"
#include "program/ops.h"

namespace rayspec {
namespace {

Expr queryGetter(const std::string& name) {
  return builtinExpr(name);
}

Stmt simple(Stmt::Kind kind) {
  Stmt s;
  s.kind = kind;
  return s;
}

// {record: {value: <getter>}}
Stmt recordValue(const std::string& getter) {
  Stmt s = simple(Stmt::Kind::Record);
  s.assigns.emplace_back("value", queryGetter(getter));
  return s;
}

// A ray_query with a triangle block, an aabb block and an after block.
Stmt rayQuery(Program triangle, Program aabb, Program after) {
  Stmt q = simple(Stmt::Kind::RayQuery);
  for (uint32_t k = 0; k < 2; ++k) {
    Stmt c = simple(Stmt::Kind::Candidates);
    c.size = k;
    c.then_ = k == 0 ? std::move(triangle) : std::move(aabb);
    q.then_.push_back(std::move(c));
  }
  q.else_ = std::move(after);
  return q;
}

std::string check(Program p, Stage stage = Stage::Raygen) {
  const auto e = checkProgram(p, stage, {}, {"value"});
  return e ? e->message : "";
}

TEST(RayQueryProgram, GettersRowsAreInOrderForEveryStage) {
  for (int b = kBiQCandT; b <= kBiQWorldDirection; ++b) {
    const BuiltinInfo& info = builtins()[b];
    EXPECT_EQ(info.stages, kAllStages) << info.name;
    EXPECT_NE(std::string(info.glsl).find("rs_query"), std::string::npos) << info.name;
  }
  // The committed row of each candidate row has the same suffix and type.
  for (int row = 0; row < kBiQueryHitRows; ++row) {
    const std::string cand = builtins()[kBiQCandT + row].name;
    const std::string committed = builtins()[kBiQCommittedT + row].name;
    EXPECT_EQ(cand.substr(cand.find('.')), committed.substr(committed.find('.')));
    EXPECT_EQ(builtins()[kBiQCandT + row].type, builtins()[kBiQCommittedT + row].type);
  }
  EXPECT_TRUE(isQueryBuiltin(builtinId(findBuiltin("committed.type"))));
  EXPECT_FALSE(isQueryBuiltin(builtinId(findBuiltin("hit_t"))));
}

TEST(RayQueryProgram, GettersOnlyInsideTheirBlocks) {
  EXPECT_EQ(check({rayQuery({recordValue("candidate.primitive_id")}, {},
                            {recordValue("committed.primitive_id")})}),
            "");
  EXPECT_NE(check({recordValue("committed.type")}).find("only inside a ray_query"),
            std::string::npos);
  EXPECT_NE(check({rayQuery({}, {}, {recordValue("candidate.instance_id")})})
                .find("after traversal it is undefined"),
            std::string::npos);
  EXPECT_NE(
      check({rayQuery({}, {recordValue("candidate.front_face")}, {})}).find("triangle candidate's"),
      std::string::npos);
  EXPECT_NE(
      check({rayQuery({recordValue("candidate.aabb_opaque")}, {}, {})}).find("AABB candidate's"),
      std::string::npos);
  EXPECT_EQ(check({rayQuery({}, {recordValue("candidate.aabb_opaque")}, {})}), "");
  // Outside raygen the query's origin and direction are required, as a trace's.
  EXPECT_NE(check({rayQuery({}, {}, {})}, Stage::ClosestHit).find("outside raygen needs 'origin'"),
            std::string::npos);
  // Every stage may cast one, any-hit and intersection too (Vulkan allows
  // rayQueryEXT in every ray tracing stage), with the same fields.
  for (Stage stage : {Stage::AnyHit, Stage::Intersection})
    EXPECT_NE(check({rayQuery({}, {}, {})}, stage).find("outside raygen needs 'origin'"),
              std::string::npos);
}

TEST(RayQueryProgram, CommitStatementsInTheirBlocks) {
  Stmt generate = simple(Stmt::Kind::Generate);
  generate.t.kind = Expr::Kind::Literal;
  generate.t.literal = {2};
  EXPECT_EQ(check({rayQuery({simple(Stmt::Kind::Confirm), simple(Stmt::Kind::TerminateQuery)},
                            {generate, simple(Stmt::Kind::TerminateQuery)}, {})}),
            "");
  EXPECT_NE(check({rayQuery({}, {simple(Stmt::Kind::Confirm)}, {})}).find("triangle block"),
            std::string::npos);
  EXPECT_NE(check({rayQuery({generate}, {}, {})}).find("aabb block"), std::string::npos);
  EXPECT_NE(check({rayQuery({}, {}, {simple(Stmt::Kind::TerminateQuery)})})
                .find("triangle or aabb block"),
            std::string::npos);
  EXPECT_NE(check({simple(Stmt::Kind::Confirm)}).find("triangle block"), std::string::npos);
}

TEST(RayQueryProgram, CandidateBlocksAreLoopBodiesOfTheirOwn) {
  // return would leave the proceed loop (break leaves it as GLSL's does:
  // allowed in a candidate block, never in `after`); trace and call cannot
  // be run again by the model's what-if runs.
  EXPECT_EQ(check({rayQuery({simple(Stmt::Kind::Break)}, {}, {})}), "");
  EXPECT_NE(check({rayQuery({}, {}, {simple(Stmt::Kind::Break)})}).find("outside a repeat"),
            std::string::npos);
  EXPECT_NE(check({rayQuery({}, {simple(Stmt::Kind::Return)}, {})}).find("'return'"),
            std::string::npos);
  EXPECT_NE(check({rayQuery({simple(Stmt::Kind::Trace)}, {}, {})}).find("'trace' in a ray_query"),
            std::string::npos);
  // `after` is the stage's own code again: return is fine there.
  EXPECT_EQ(check({rayQuery({}, {}, {simple(Stmt::Kind::Return)})}), "");
}

TEST(RayQueryProgram, NestingIsBoundedAndReadsTheInnermost) {
  // Inside an inner query's after block, the outer candidate is not readable.
  Stmt inner = rayQuery({}, {}, {recordValue("candidate.t")});
  EXPECT_NE(check({rayQuery({inner}, {}, {})}).find("after traversal"), std::string::npos);
  Stmt q = rayQuery({}, {}, {});
  for (uint32_t depth = 1; depth < kMaxQueryNesting; ++depth) q = rayQuery({q}, {}, {});
  EXPECT_EQ(check({q}), "");
  EXPECT_NE(check({rayQuery({q}, {}, {})}).find("nested more than"), std::string::npos);
}

}  // namespace
}  // namespace rayspec
