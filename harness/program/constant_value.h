// The value of an expression that reads nothing at run time: literals and
// operators over them, folded with the meaning ops.h gives them. The parser's
// static checks (an SBT index, a divisor) use it; anything else is dynamic and
// left to the model. Needs the types typeCheck fills in.
#pragma once

#include <cstdint>
#include <optional>

#include "program/program.h"

namespace rayspec {

// A Uint expression's value: Uint literals and add, sub, mul (modulo 2^32),
// div, mod (not by zero), min, max over them. nullopt when it reads a
// built-in or a shader record, or divides by zero.
std::optional<uint32_t> constantUint(const Expr& e);

// A Float expression's value when it is a literal (a Uint literal retyped as
// a Float included).
std::optional<double> constantFloat(const Expr& e);

}  // namespace rayspec
