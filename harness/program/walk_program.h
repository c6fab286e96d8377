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
// Every expression of a program (nested ones included), to change in place.
void editExpressions(Program& p, const std::function<void(Expr&)>& visit);

}  // namespace rayspec
