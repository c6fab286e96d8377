// traceRayEXT and executeCallableEXT statements as GLSL. Arguments are
// evaluated into locals first, then the outgoing payload / callable data is
// reset, then the call is made: an argument that reads child.* / callee.* (or,
// in raygen, payload.*) sees the result of the previous trace or call.
#pragma once

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

void emitTrace(const Stmt& s, const StageContext& ctx, GlslWriter& out);
void emitCall(const Stmt& s, const StageContext& ctx, GlslWriter& out);

}  // namespace rayspec
