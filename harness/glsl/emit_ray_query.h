// Raygen's traces as ray query loops (Pipeline::ray_query, --through
// ray-query, R-RQ-EQUIV). Each hit group's any-hit, intersection and
// closest-hit and each miss program become functions of raygen:
//   while (rayQueryProceedEXT) a triangle candidate runs the any-hit of its
//   record's group (ignore leaves it, accept confirms it, terminate confirms
//   it and ends the query) and an AABB candidate the group's intersection,
//   whose reports become rayQueryGenerateIntersectionEXT at the reported t
//   when that t lies in [tmin, committed t] and the any-hit (not run for an
//   opaque box) accepts; then the committed intersection runs the closest-hit
//   of its record's group (unless skip_closest_hit) or, with none, the miss
//   the trace names. The hit record is the instance's offset + geometry x
//   stride + offset, as traceRayEXT's; its group comes from the case's SBT.
// The other stages stay in the pipeline and never run.
#pragma once

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

// Raygen's uses grown by what the inlined programs use (their record fields,
// counters, calls, scene reads).
void addInlinedUses(StageContext& raygen);

// The query, its state and every inlined program, before raygen's own code.
void emitInlinedStages(const StageContext& raygen, GlslWriter& out);

// One trace in raygen, its arguments in rs_flags .. rs_tmax and its payload
// started in rs_payload_<location>: the query loop and its closest-hit or miss.
void emitRayQueryTrace(const Stmt& s, const StageContext& ctx, GlslWriter& out);

}  // namespace rayspec
