// What a case's ray query form (Pipeline::ray_query: every trace a ray query
// loop in raygen running the hit group and miss programs inlined,
// glsl/emit_ray_query.h) cannot express. Used by --through ray-query
// (metamorphic/feature_path.h), which sends a case there only when nothing
// is in the way, and by the parser for a case that asks for it itself
// (pipeline.traces: ray_query).
#pragma once

#include <string>

#include "case/case.h"

namespace rayspec {

// "" when the case can be traced by ray queries, else what is in the way.
// `own`: the case asks for it itself (its own pipeline.traces is not a reason).
// With Pipeline::from_compute, what raygen as a compute shader cannot do too.
std::string rayQueryObstacle(const Case& c, bool own = false);

// What is in the way of --through ray-query-compute: rayQueryObstacle, and
// what a compute shader cannot do (callables, shader record blocks).
std::string computeRayQueryObstacle(const Case& c);

}  // namespace rayspec
