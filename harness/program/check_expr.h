// Internal to the program module: expression checks that keep the location of
// the offending node (typeCheck in ops.h returns only the message).
#pragma once

#include <optional>

#include "program/locals.h"
#include "program/ops.h"

namespace rayspec {

// Fills e.type (and its arguments'); the error names the innermost bad node.
std::optional<ProgramError> checkExpr(Expr& e, Stage stage, const LocalScope* locals = nullptr);

// Checks e and requires type `want`; a Uint literal is accepted (and retyped)
// where a Float is wanted. `what` names the slot in the message ("report t").
std::optional<ProgramError> checkExprAs(Expr& e, Stage stage, ValueType want,
                                        const std::string& what,
                                        const LocalScope* locals = nullptr);

// After typing: an integer literal over 32 bits (Expr::wide) that did not
// become an int64 (below 2^63) or uint64 value is an error at its place.
std::optional<ProgramError> checkWideLiterals(const Program& p);

}  // namespace rayspec
