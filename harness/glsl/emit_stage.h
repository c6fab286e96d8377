// The whole GLSL of one stage: header, #defines from the C++ tables, the
// shared pieces of shaders/ it needs, its interface variables and main().
#pragma once

#include "glsl/generate_glsl.h"

namespace rayspec {

// incoming_location: the location whose payload type a miss, closest-hit or
// any-hit receives (Pipeline::miss_payload, HitGroup::payload), or whose
// callable data type a callable receives (Pipeline::callable_data);
// procedural: a stage of a hit group with an intersection shader, whose hit
// attribute is pipeline.hit_attribute's words and sized members.
GeneratedShader emitStage(const Case& c, const Plan& plan, Stage stage, const std::string& name,
                          const Program& program, uint32_t incoming_location = 0,
                          bool procedural = false);

}  // namespace rayspec
