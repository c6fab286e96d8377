// program/op_table.h: one row per operator, from which the parser's names,
// the typing rules, the GLSL patterns and the model's ids all come.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "program/ops.h"

namespace rayspec {
namespace {

TEST(OpTable, EveryRowIsItsOwnIdAndName) {
  std::set<std::string> names;
  for (size_t i = 0; i < ops().size(); ++i) {
    const OpInfo& o = ops()[i];
    EXPECT_EQ(static_cast<size_t>(o.id), i) << o.name;
    EXPECT_EQ(opNamed(o.name), o.id) << o.name;
    EXPECT_EQ(&opInfo(o.id), &o) << o.name;
    EXPECT_STREQ(nameOf(o.id), o.name);
    EXPECT_TRUE(names.insert(o.name).second) << "twice: " << o.name;
    EXPECT_LE(o.min_args, o.max_args) << o.name;
  }
  EXPECT_EQ(opNamed("frobnicate"), Op::None);
  EXPECT_EQ(findOp("frobnicate"), nullptr);
}

// A pattern names only arguments the op may have; the ops without one are
// those whose GLSL depends on more than their arguments.
TEST(OpTable, GlslPatternsNameOnlyTheirArguments) {
  const std::set<Op> spelled = {Op::Load,       Op::PayloadWord, Op::ChildWord,  Op::CallWord,
                                Op::CalleeWord, Op::RecordUint,  Op::RecordFloat};
  for (const OpInfo& o : ops()) {
    EXPECT_EQ(o.glsl == nullptr, spelled.count(o.id) == 1) << o.name;
    if (!o.glsl) continue;
    const std::string p = o.glsl;
    for (size_t i = p.find('$'); i != std::string::npos; i = p.find('$', i + 1)) {
      ASSERT_LT(i + 1, p.size()) << o.name;
      const char c = p[i + 1];
      if (c >= '0' && c <= '9')
        EXPECT_LT(c - '0', o.min_args) << o.name << ": " << p;
      else
        EXPECT_TRUE(c == ',' || c == '&' || c == '|') << o.name << ": " << p;
    }
  }
}

TEST(OpTable, TypeCheckerResolvesTheIdOfANamedOp) {
  Expr e;
  e.kind = Expr::Kind::Op;
  e.name = "max";  // built by name only: the checker fills the id
  Expr a;
  a.literal = {1};
  Expr b;
  b.literal = {2};
  e.args = {a, b};
  ASSERT_TRUE(typeCheck(e, Stage::Raygen));
  EXPECT_EQ(e.op, Op::Max);
  EXPECT_EQ(e.type, ValueType::Uint);
}

}  // namespace
}  // namespace rayspec
