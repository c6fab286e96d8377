// pipeline.tlas_function: every traceRayEXT and rayQueryInitializeEXT of a
// stage is made inside a function that takes the top level as an
// accelerationStructureEXT parameter, the caller passing the element it
// names (rs_tlas, rs_tlas[k], rs_tlas[nonuniformEXT(i)]).
#pragma once

#include <string>

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

// The stage's functions, before anything that traces: one a payload
// location its traces pass (traceRayEXT's location is a constant), and one
// for its ray queries. Nothing without pipeline.tlas_function.
void emitTlasFunctions(const StageContext& ctx, GlslWriter& out);

// The call that traces on `tlas` with the trace locals rs_flags .. rs_tmax
// to the GLSL payload location `location`: traceRayEXT itself, or the
// function above.
std::string traceCall(const StageContext& ctx, const std::string& tlas, uint32_t location);
// hitObjectTraceRayNV into the stage's hit object (rs_hit_object) with the
// same locals; never through pipeline.tlas_function's functions.
std::string hitObjectTraceCall(const std::string& tlas, uint32_t location);
// The same for rayQueryInitializeEXT of `query` (rs_flags, rs_cull_mask,
// rs_origin, rs_tmin, rs_direction, rs_tmax).
std::string queryInitCall(const StageContext& ctx, const std::string& query,
                          const std::string& tlas);

}  // namespace rayspec
