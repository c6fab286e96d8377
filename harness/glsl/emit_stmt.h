// The statements of a stage program as GLSL (the body of main()).
#pragma once

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

void emitProgram(const Program& program, const StageContext& ctx, GlslWriter& out);

// "RS_FIELD_HIT_T" / "RS_BIT_HIT_T" for a record field name.
std::string fieldOffsetMacro(const std::string& field);
std::string fieldBitMacro(const std::string& field);

}  // namespace rayspec
