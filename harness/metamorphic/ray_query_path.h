// --through ray-query: every trace of a case made a ray query loop in raygen
// that runs the hit group and miss programs inlined (Pipeline::ray_query,
// glsl/emit_ray_query.h), where they can be; R-RQ-EQUIV says the observations
// stay those of traceRayEXT, so the model's expectation stays the case's own.
#pragma once

#include <string>

#include "case/case.h"

namespace rayspec {

// Sets c.pipeline.ray_query, or false with *why_not: what the inlined form
// does not express.
bool inlinedByRayQuery(Case& c, std::string* why_not);

}  // namespace rayspec
