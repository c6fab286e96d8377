// glsl/emit_expr.cpp: an operator's GLSL is its row's pattern
// (program/op_table.h) with its arguments, or spelled by the emitter.
#include <gtest/gtest.h>

#include <string>

#include "glsl/emit_expr.h"
#include "program/ops.h"

namespace rayspec {
namespace {

Expr uintArg(const std::string& local) {
  Expr e;
  e.kind = Expr::Kind::Local;
  e.name = local;
  e.type = ValueType::Uint;
  return e;
}

TEST(EmitOps, FromThePattern) {
  const Case c;
  const Plan plan;
  const StageContext ctx{c, plan, Stage::Raygen};
  const SourceLoc at;
  const Expr three = opExpr(Op::And,
                            {opExpr(Op::Odd, {uintArg("a")}, ValueType::Bool, at),
                             opExpr(Op::Even, {uintArg("b")}, ValueType::Bool, at),
                             opExpr(Op::Odd, {uintArg("c")}, ValueType::Bool, at)},
                            ValueType::Bool, at);
  EXPECT_EQ(emitExpr(three, ctx),
            "(((v_a & 1u) != 0u) && ((v_b & 1u) == 0u) && ((v_c & 1u) != 0u))");
  const Expr shift = opExpr(Op::Shl, {uintArg("a"), uintArg("b")}, ValueType::Uint, at);
  EXPECT_EQ(emitExpr(shift, ctx), "(v_a << (v_b & 31u))");
  Expr word = opExpr(Op::CalleeWord, {uintArg("i")}, ValueType::Uint, at);
  EXPECT_EQ(emitExpr(word, ctx), "callee.words[(v_i) % uint(callee.words.length())]");
  // setOp makes it another op, name and id together.
  setOp(word, Op::CallWord);
  EXPECT_EQ(word.name, "call_word");
  EXPECT_EQ(emitExpr(word, ctx), "call.words[(v_i) % uint(call.words.length())]");
}

// A sized scalar's literal is its constructor of a value it holds exactly.
TEST(EmitOps, SizedLiteralsAndConversions) {
  const Case c;
  const Plan plan;
  const StageContext ctx{c, plan, Stage::Raygen};
  const SourceLoc at;
  Expr big;
  big.kind = Expr::Kind::Literal;
  big.type = ValueType::Uint64;
  big.literal = {1099511627776.0};
  EXPECT_EQ(emitExpr(big, ctx), "uint64_t(1099511627776ul)");
  Expr wide = big;  // over 2^53: as written (Expr::wide), not as its double
  wide.literal = {18446744047939747845.0};
  wide.wide = 18446744047939747845ull;
  EXPECT_EQ(emitExpr(wide, ctx), "uint64_t(18446744047939747845ul)");
  wide.type = ValueType::Int64;
  wide.wide = 0x7FFFFFFFFFFFFFFDull;
  EXPECT_EQ(emitExpr(wide, ctx), "int64_t(9223372036854775805ul)");
  Expr d = big;
  d.type = ValueType::Float64;
  d.literal = {0.1};
  EXPECT_EQ(emitExpr(d, ctx), "float64_t((0.10000000000000001lf))");
  Expr h = big;
  h.type = ValueType::Float16;
  h.literal = {-20.5};
  EXPECT_EQ(emitExpr(h, ctx), "float16_t((-20.5))");
  Expr i8 = big;
  i8.type = ValueType::Int8;
  i8.literal = {100};
  const Expr narrowed = opExpr(Op::ToInt8, {uintArg("a")}, ValueType::Int8, at);
  EXPECT_EQ(emitExpr(opExpr(Op::Add, {narrowed, i8}, ValueType::Int8, at), ctx),
            "(int8_t(v_a) + int8_t(100u))");
}

}  // namespace
}  // namespace rayspec
