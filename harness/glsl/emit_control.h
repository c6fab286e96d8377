// Control flow and local variables of the stage vocabulary as GLSL, and the
// functions (pipeline.functions) a stage program invokes.
#pragma once

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

// let, set, array, store, repeat, break, continue, switch, invoke, return.
void emitControl(const Stmt& s, const StageContext& ctx, GlslWriter& out);

// A GLSL function for every function the program invokes (nested ones too),
// callees before callers, each once.
void emitFunctions(const Program& program, const StageContext& ctx, GlslWriter& out);

}  // namespace rayspec
