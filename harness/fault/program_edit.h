// Editing the stage programs and flags of a case in place (internal to
// fault/): the case mutations that stand for a device breaking a rule.
#pragma once

#include <functional>

#include "case/case.h"

namespace rayspec {

// Every program of the pipeline, with its stage: raygen, miss, the three
// stages of each hit group, callables.
void forEachProgram(Pipeline& p, const std::function<void(Program&, Stage)>& visit);
void forEachProgram(const Pipeline& p, const std::function<void(const Program&, Stage)>& visit);
// Every statement list (a program and every nested then/else block).
void forEachBlock(Program& p, const std::function<void(std::vector<Stmt>&)>& visit);
// Every statement, nested ones included.
void forEachStmt(Program& p, const std::function<void(Stmt&)>& visit);
// A Uint literal written at `loc`, for the expressions a mutation puts in.
Expr uintLiteral(uint32_t v, const SourceLoc& loc);
// "N what" (empty when n is 0): what a mutation changed, or nothing.
std::string describeCount(size_t n, const std::string& what);

// Removes the statements `drop` selects (nested ones too); returns how many.
size_t removeStmts(Program& p, const std::function<bool(const Stmt&)>& drop);

// Clears `bits` of the ray flags everywhere a trace gets them: every launch
// ray, the defaults for nested traces, and literal `flags` of trace
// statements. Returns whether a flag was set somewhere.
bool clearRayFlags(Case& c, uint32_t bits);
// Sets `bits` in the same places (literal trace flags only).
bool setRayFlags(Case& c, uint32_t bits);
// Whether some trace may use one of `bits` (a non-literal trace flags
// expression may use any).
bool mayUseRayFlags(const Case& c, uint32_t bits);

// The SBT region as the pipeline uses it: the written one, or the default
// one record per shader / group, in order.
std::vector<SbtRecord>& explicitSbt(std::vector<SbtRecord>& region, size_t shaders);

}  // namespace rayspec
