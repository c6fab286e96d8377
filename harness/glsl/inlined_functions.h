// Functions (pipeline.functions) invoked by a program inlined in a ray query
// host (glsl/emit_ray_query.h). A stage's function reads the stage's
// interface; inlined, that interface is the locals and parameters of the
// program's function, so each function is written once per inlined program
// and level, named after both, and takes them as extra parameters. An
// any-hit's ignore or terminate inside one sets rs_ah_verdict and returns;
// the caller returns that verdict after the invoke, as the pipeline's
// any-hit ends there.
#pragma once

#include <string>

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

// rs_fn_<name>, and for an inlined program _<its shader>[_d<level>].
std::string functionName(const std::string& name, const StageContext& ctx);

// ", inout RsPayload payload, ..." after a function's own parameters, and
// the matching arguments; "" outside inlined programs.
std::string inlinedFunctionParams(const StageContext& ctx);
std::string inlinedFunctionArgs(const StageContext& ctx);

// After an invoke in an inlined program: an any-hit's verdict or an
// intersection's terminated query ends it, as in the stage.
void afterInlinedInvoke(const StageContext& ctx, GlslWriter& out);

// The GLSL of ignore / terminate in an inlined any-hit.
std::string inlinedVerdict(bool ignore, const StageContext& ctx);

}  // namespace rayspec
