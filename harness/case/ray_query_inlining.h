// What a case's ray query forms cannot express. Pipeline::ray_query: every
// trace a ray query loop in raygen running the hit group and miss programs
// inlined, the traces of inlined closest-hit and miss programs nested loops,
// one level each (glsl/emit_ray_query.h). Pipeline::ray_query_in_hit: raygen
// keeps traceRayEXT, the traces of closest-hit and miss stages are those
// loops inside the stage. Used by --through ray-query and ray-query-in-hit
// (metamorphic/feature_path.h), which send a case there only when nothing is
// in the way, and by the parser for a case that asks for a form itself
// (pipeline.traces: ray_query, ray_query_in_hit).
#pragma once

#include <cstdint>
#include <string>

#include "case/case.h"

namespace rayspec {

// A level's trace is a function every trace site of the level above calls,
// and compilers inline every call: T trace sites in closest-hit and miss
// programs make T^(L-1) copies of level L. More copies than this (lavapipe
// compiles a few dozen in seconds) is an obstacle.
constexpr uint64_t kMaxInlinedCopies = 64;

// "" when the case can be traced by ray queries, else what is in the way.
// `own`: the case asks for it itself (its own pipeline.traces is not a reason).
// With Pipeline::from_compute, what raygen as a compute shader cannot do too.
std::string rayQueryObstacle(const Case& c, bool own = false);

// What is in the way of --through ray-query-compute: rayQueryObstacle, and
// what a compute shader cannot do (callables, shader record blocks).
std::string computeRayQueryObstacle(const Case& c);

// The same for its closest-hit and miss stages' traces alone; a case whose
// closest-hit and miss programs never trace has nothing to send there.
std::string rayQueryInHitObstacle(const Case& c, bool own = false);

// Some closest-hit or miss program traces (nested traces).
bool hitOrMissTraces(const Pipeline& p);

}  // namespace rayspec
