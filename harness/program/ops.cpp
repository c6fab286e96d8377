// The table of operators, generated from program/op_table.h. Typing rules are
// in type_check.cpp.
#include "program/ops.h"

namespace rayspec {
namespace {

constexpr int kManyArgs = 16;  // and/or take 2 or more arguments
using stage_letters::A;
using stage_letters::C;
using stage_letters::I;
using stage_letters::K;
using stage_letters::M;
using stage_letters::R;

}  // namespace

const std::vector<OpInfo>& ops() {
#define RAYSPEC_OP_ROW(id, name, min_args, max_args, stages, typing, glsl, meaning) \
  {Op::id, name, min_args, max_args, stages, OpTyping::typing, glsl, meaning},
  static const std::vector<OpInfo> table = {RAYSPEC_OPS(RAYSPEC_OP_ROW)};
#undef RAYSPEC_OP_ROW
  return table;
}

const OpInfo* findOp(const std::string& name) {
  const std::optional<Op> op = valueNamed<Op>(name);
  return op ? &opInfo(*op) : nullptr;
}

const OpInfo& opInfo(Op op) {
  return ops()[static_cast<size_t>(op)];
}

Op opNamed(const std::string& name) {
  return valueNamed<Op>(name).value_or(Op::None);
}

std::optional<WordArray> wordArrayOf(Op op) {
  static_assert(static_cast<int>(Op::CalleeWord) - static_cast<int>(Op::PayloadWord) ==
                    static_cast<int>(WordArray::Callee) - static_cast<int>(WordArray::Payload),
                "payload_word .. callee_word in WordArray's order");
  if (op < Op::PayloadWord || op > Op::CalleeWord) return std::nullopt;
  return static_cast<WordArray>(static_cast<int>(op) - static_cast<int>(Op::PayloadWord));
}

Expr opExpr(Op op, std::vector<Expr> args, ValueType type, const SourceLoc& loc) {
  Expr e;
  e.kind = Expr::Kind::Op;
  setOp(e, op);
  e.type = type;
  e.loc = loc;
  e.args = std::move(args);
  return e;
}

void setOp(Expr& e, Op op) {
  e.op = op;
  e.name = nameOf(op);
}

}  // namespace rayspec
