// A ray query's id getters are observations of the id (metamorphic/
// id_observations.h): a permutation keeps what a query's program sees.
#include <gtest/gtest.h>

#include "metamorphic/id_observations.h"
#include "metamorphic/motion_spec.h"
#include "metamorphic/transform_case.h"
#include "program/ops.h"

namespace rayspec {
namespace {

Expr getter(const std::string& name) {
  return builtinExpr(name);
}

Expr compare(const std::string& op, Expr a, double literal) {
  Expr lit;
  lit.kind = Expr::Kind::Literal;
  lit.literal = {literal};
  Expr e;
  e.kind = Expr::Kind::Op;
  e.name = op;
  e.op = opNamed(op);
  e.args = {std::move(a), lit};
  return e;
}

// raygen: ray_query whose triangle block holds `if: cond` and whose after
// block records `value`.
Pipeline queryPipeline(Expr cond, Expr value) {
  Stmt ifs;
  ifs.kind = Stmt::Kind::If;
  ifs.cond = std::move(cond);
  Stmt block;
  block.kind = Stmt::Kind::Candidates;
  block.then_ = {ifs};
  Stmt rec;
  rec.kind = Stmt::Kind::Record;
  rec.assigns.emplace_back("value", std::move(value));
  Stmt q;
  q.kind = Stmt::Kind::RayQuery;
  q.then_ = {block};
  q.else_ = {rec};
  Pipeline p;
  p.raygen = {q};
  return p;
}

TEST(QueryIdObservations, CandidateAndCommittedGettersObserveTheId) {
  const Pipeline p = queryPipeline(compare("lt", getter("candidate.instance_id"), 3),
                                   getter("committed.primitive_id"));
  const IdObservations inst = observeId(p, kBiInstance);
  EXPECT_FALSE(inst.exact);
  ASSERT_EQ(inst.below.size(), 1u);
  EXPECT_EQ(inst.below[0], 3u);
  EXPECT_NE(inst.classOf(2), inst.classOf(3));
  EXPECT_EQ(inst.classOf(0), inst.classOf(2));
  // committed.primitive_id recorded in a free field: the id itself.
  EXPECT_TRUE(observeId(p, kBiPrimitive).exact);
  EXPECT_FALSE(
      observeId(queryPipeline(compare("eq", getter("candidate.t"), 1), getter("query.ray_tmin")),
                kBiPrimitive)
          .exact);
}

// A ray query that gives its own direction would not move with the case.
TEST(QueryIdObservations, AQueryWithItsOwnRayIsNotMoved) {
  Case c;
  c.pipeline = queryPipeline(compare("lt", getter("candidate.t"), 3), getter("query.ray_tmin"));
  const Result<RigidMotion> m = parseMotionSpec("-y,x,z");
  ASSERT_TRUE(m.ok());
  EXPECT_TRUE(moveCase(c, *m, MoveScope::Verdict).ok());
  Expr dir;
  dir.kind = Expr::Kind::Literal;
  dir.type = ValueType::Vec3;
  dir.literal = {1, 0, 0};
  c.pipeline.raygen[0].trace.direction.push_back(dir);
  const Result<Case> moved = moveCase(c, *m, MoveScope::Verdict);
  ASSERT_FALSE(moved.ok());
  EXPECT_NE(moved.error().message.find("ray query gives its own origin or direction"),
            std::string::npos);
}

}  // namespace
}  // namespace rayspec
