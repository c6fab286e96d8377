// traceRayEXT statements as GLSL. Arguments are evaluated into locals first,
// then the outgoing payload is reset, then the trace is made: an argument that
// reads child.* (or, in raygen, payload.*) sees the result of the previous
// trace (emit_call_data.h does the same for executeCallableEXT).
#pragma once

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

void emitTrace(const Stmt& s, const StageContext& ctx, GlslWriter& out);
// The hit object's statements (GL_NV_shader_invocation_reorder): execute
// (hitObjectExecuteShaderNV, its payload as a trace's), record_miss,
// record_empty and reorder (reorderThreadNV). A trace into the hit object is
// emitTrace's (hitObjectTraceRayNV).
void emitHitObjectStatement(const Stmt& s, const StageContext& ctx, GlslWriter& out);

// The top level a trace or ray_query names (TraceArgs::tlas or tlas_index):
// its index as GLSL (a constant, or rs_tlas_i % the top levels: a dynamic
// index wraps as an array local's does), and the acceleration structure
// operand (rs_tlas, rs_tlas[k], rs_tlas[nonuniformEXT(..)]: an index that
// may differ between invocations).
std::string tlasIndex(const TraceArgs& t, const StageContext& ctx);
std::string tlasOperand(const TraceArgs& t, const StageContext& ctx);
// rs_tlas_i := the index expression, where there is one (evaluated with the
// other arguments, before the payload is reset).
void tlasIndexLocal(const TraceArgs& t, const StageContext& ctx, GlslWriter& out);

}  // namespace rayspec
