// Control flow and local variables of the stage vocabulary as GLSL, and the
// functions (pipeline.functions) a stage program invokes.
#pragma once

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

// let, set, array, struct, store, repeat, break, continue, switch, invoke, return.
void emitControl(const Stmt& s, const StageContext& ctx, GlslWriter& out);

// The GLSL struct type of a struct local's member list: its name, made of
// the members' types and names (RsStruct_int8_a_vec3_b), and its definition,
// one for each distinct list of the case (Plan::struct_types), at file scope.
std::string structTypeName(const std::vector<std::pair<std::string, ValueType>>& members);
void emitStructTypes(const StageContext& ctx, GlslWriter& out);

// A GLSL function for every function the program invokes (nested ones too),
// callees before callers, each once.
void emitFunctions(const Program& program, const StageContext& ctx, GlslWriter& out);

}  // namespace rayspec
