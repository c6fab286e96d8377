// Visits every statement and expression of a program, nested ones included.
#pragma once

#include <functional>

#include "program/program.h"

namespace rayspec {

void walkStatements(const Program& p, const std::function<void(const Stmt&)>& visit);
void walkExpressions(const Program& p, const std::function<void(const Expr&)>& visit);
// The expressions of s itself (not of the statements nested in it).
void walkOwnExpressions(const Stmt& s, const std::function<void(const Expr&)>& visit);
// Whether the rest of the program may not run after s: s is or holds an
// ignore, a terminate or a return (conservative: a function's return only
// ends the function).
bool mayEndProgram(const Stmt& s);
// Whether a ray_query's candidate block may leave the query's proceed loop:
// it holds a `break` outside any repeat and switch (in an if, or in the
// `after` of a ray_query nested in it), as GLSL's break leaves the innermost
// loop.
bool leavesQueryLoop(const Program& block);
// Every expression of a program (nested ones included), to change in place.
void editExpressions(Program& p, const std::function<void(Expr&)>& visit);

}  // namespace rayspec
