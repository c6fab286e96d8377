// One expression of the stage vocabulary as GLSL (harness/program/builtins.h
// and ops.h give the meaning; this file gives the spelling).
#pragma once

#include <string>

#include "glsl/stage_context.h"

namespace rayspec {

// GLSL for e. An expression this stage cannot evaluate becomes a call of an
// undeclared function named after the problem, so glslang reports it with the
// line (the type checker of harness/program rejects such cases first).
std::string emitExpr(const Expr& e, const StageContext& ctx);

// GLSL type name of a value type ("uint", "vec3", ...).
const char* glslType(ValueType t);

// A local variable's GLSL name (var.NAME -> v_NAME).
// A member STRUCT.MEMBER is v_STRUCT.m_MEMBER (GLSL keywords free as names).
std::string localName(const std::string& name);
// An array local's index expression: index modulo its size, as the model does.
std::string arrayIndex(const std::string& array, const std::string& index);

}  // namespace rayspec
