#include "program/constant_value.h"

#include <algorithm>

namespace rayspec {

std::optional<uint32_t> constantUint(const Expr& e) {
  if (e.type != ValueType::Uint) return std::nullopt;
  if (e.kind == Expr::Kind::Literal) {
    if (e.literal.size() != 1 || e.wide) return std::nullopt;  // over 32 bits: no Uint
    return static_cast<uint32_t>(e.literal[0]);
  }
  if (e.kind != Expr::Kind::Op || e.args.size() != 2) return std::nullopt;
  const std::optional<uint32_t> a = constantUint(e.args[0]), b = constantUint(e.args[1]);
  if (!a || !b) return std::nullopt;
  switch (e.op) {
    case Op::Add:
      return *a + *b;
    case Op::Sub:
      return *a - *b;
    case Op::Mul:
      return *a * *b;
    case Op::Div:
      return *b ? std::optional<uint32_t>(*a / *b) : std::nullopt;
    case Op::Mod:
      return *b ? std::optional<uint32_t>(*a % *b) : std::nullopt;
    case Op::Min:
      return std::min(*a, *b);
    case Op::Max:
      return std::max(*a, *b);
    default:
      return std::nullopt;
  }
}

std::optional<double> constantFloat(const Expr& e) {
  if (e.kind != Expr::Kind::Literal || e.literal.size() != 1) return std::nullopt;
  if (e.type != ValueType::Float && e.type != ValueType::Uint) return std::nullopt;
  return e.literal[0];
}

}  // namespace rayspec
