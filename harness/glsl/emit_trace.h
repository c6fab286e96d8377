// traceRayEXT statements as GLSL. Arguments are evaluated into locals first,
// then the outgoing payload is reset, then the trace is made: an argument that
// reads child.* (or, in raygen, payload.*) sees the result of the previous
// trace (emit_call_data.h does the same for executeCallableEXT).
#pragma once

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

void emitTrace(const Stmt& s, const StageContext& ctx, GlslWriter& out);

}  // namespace rayspec
