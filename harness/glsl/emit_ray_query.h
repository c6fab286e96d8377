// Traces as ray query loops (Pipeline::ray_query: raygen's, --through
// ray-query; Pipeline::ray_query_in_hit: a closest-hit's or miss's,
// --through ray-query-in-hit; R-RQ-EQUIV). The host stage (glsl/
// inlined_levels.h) holds each hit group's any-hit, intersection and
// closest-hit and each miss program as functions:
//   while (rayQueryProceedEXT) a triangle candidate runs the any-hit of its
//   record's group (ignore leaves it, accept confirms it, terminate confirms
//   it and ends the query) and an AABB candidate the group's intersection,
//   whose reports become rayQueryGenerateIntersectionEXT at the reported t
//   when that t lies in [tmin, committed t] and the any-hit (not run for an
//   opaque box) accepts; then the committed intersection runs the closest-hit
//   of its record's group (unless skip_closest_hit) or, with none, the miss
//   the trace names. The hit record is the instance's offset + geometry x
//   stride + offset, as traceRayEXT's; its group, the miss record's program
//   and the records' data come from the case's SBT, laid out as tables in a
//   buffer (glsl/bindings.h, packSbtTables).
// A trace made by an inlined closest-hit or miss is the same loop one level
// down, with its own query, state and copies of the programs (levels are
// written deepest first, each a function rs_trace[_d<L>]). The stages the
// host replaces stay in the pipeline and never run from it.
#pragma once

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

// The host's uses grown by what the inlined programs use (their record
// fields, counters, calls, scene reads).
void addInlinedUses(StageContext& host);

// Before shaders/scene.glsl and sphere.glsl in a host: the box candidate
// they read is the one the running loop sets (each level has its own query).
void emitCandidateMacros(GlslWriter& out);

// The queries, their state and every inlined program at every level, before
// the host's own code. Level 1's query, rs_rq, is declared before them.
void emitInlinedStages(const StageContext& host, GlslWriter& out);

// One trace of the host or of an inlined program, its arguments in rs_flags
// .. rs_tmax and its payload started in rs_payload_<location>: a call of the
// next level's trace function. False where the trace is beyond the last
// level (pipeline.max_recursion), skipped as the model skips it: the payload
// is then no result.
bool emitRayQueryTrace(const Stmt& s, const StageContext& ctx, GlslWriter& out);

}  // namespace rayspec
