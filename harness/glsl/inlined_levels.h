// Which stage's traces become ray query loops, and how deep they nest
// (glsl/emit_ray_query.h). A trace made by an inlined closest-hit or miss is
// a query one level down: GLSL has no recursion, so the inlined programs,
// the query and its state are written once per level, level 1 under their
// plain names and level L > 1 under names ending in _d<L> (the state by
// #define inside the level's block, the functions by name).
#pragma once

#include <cstdint>
#include <string>

#include "glsl/glsl_writer.h"
#include "glsl/stage_context.h"

namespace rayspec {

// The stage holds the inlined programs and its own traces are ray query
// loops: raygen under Pipeline::ray_query, a closest-hit or miss that traces
// under Pipeline::ray_query_in_hit.
bool hostsInlinedStages(const Case& c, Stage stage, const StageUses& uses);

// Every trace this stage makes is a ray query loop: a host's and an inlined
// program's.
bool tracesByRayQuery(const StageContext& ctx);

// How many levels of inlined programs the host writes. Raygen's traces run
// their programs at trace depth 1, so its levels are pipeline.max_recursion
// when a closest-hit or miss traces, else 1; a closest-hit or miss runs at
// depth 1 or more, so its traces need at most max_recursion - 1 levels. A
// trace made at the last level would go beyond max_recursion, which the
// model takes as undefined and skips (R-RECURSION, R-UB): the loop skips it
// too.
uint32_t inlinedLevels(const StageContext& host);

// `name` at `level`: itself at level 1, else name_d<level>.
std::string atLevel(const std::string& name, uint32_t level);

// The state of one level's query that built-in spellings and shared code
// read by plain name (rs_rq, rs_q_flags, rs_current_tmax(), ...): level
// L > 1 opens its block with #define NAME NAME_d<L> and closes it with #undef.
void openLevel(uint32_t level, GlslWriter& out);
void closeLevel(uint32_t level, GlslWriter& out);

}  // namespace rayspec
