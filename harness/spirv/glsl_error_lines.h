// Error messages that quote the GLSL they are about.
#pragma once

#include <string>

#include "program/program.h"

namespace rayspec {

// Text of line `line` (1-based) of glsl; empty when out of range.
std::string glslLine(const std::string& glsl, int line);

// Copies a glslang info log and, after each "ERROR: 0:N:" / "WARNING: 0:N:"
// message, adds "  N | <text of line N>".
std::string quoteGlslLines(const std::string& log, const std::string& glsl);

// For a module SPIRV-Tools rejected: recompiles with debug line info,
// validates again and names the GLSL line of the failing instruction.
std::string describeSpirvFailure(const std::string& glsl, Stage stage, bool compute = false);

}  // namespace rayspec
