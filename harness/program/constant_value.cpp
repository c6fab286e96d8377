#include "program/constant_value.h"

#include <algorithm>

namespace rayspec {

std::optional<uint32_t> constantUint(const Expr& e) {
  if (e.type != ValueType::Uint) return std::nullopt;
  if (e.kind == Expr::Kind::Literal) {
    if (e.literal.size() != 1) return std::nullopt;
    return static_cast<uint32_t>(e.literal[0]);
  }
  if (e.kind != Expr::Kind::Op || e.args.size() != 2) return std::nullopt;
  const std::optional<uint32_t> a = constantUint(e.args[0]), b = constantUint(e.args[1]);
  if (!a || !b) return std::nullopt;
  if (e.name == "add") return *a + *b;
  if (e.name == "sub") return *a - *b;
  if (e.name == "mul") return *a * *b;
  if (e.name == "div") return *b ? std::optional<uint32_t>(*a / *b) : std::nullopt;
  if (e.name == "mod") return *b ? std::optional<uint32_t>(*a % *b) : std::nullopt;
  if (e.name == "min") return std::min(*a, *b);
  if (e.name == "max") return std::max(*a, *b);
  return std::nullopt;
}

std::optional<double> constantFloat(const Expr& e) {
  if (e.kind != Expr::Kind::Literal || e.literal.size() != 1) return std::nullopt;
  if (e.type != ValueType::Float && e.type != ValueType::Uint) return std::nullopt;
  return e.literal[0];
}

}  // namespace rayspec
