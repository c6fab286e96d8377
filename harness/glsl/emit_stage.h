// The whole GLSL of one stage: header, #defines from the C++ tables, the
// shared pieces of shaders/ it needs, its interface variables and main().
#pragma once

#include "glsl/generate_glsl.h"

namespace rayspec {

GeneratedShader emitStage(const Case& c, const Plan& plan, Stage stage, const std::string& name,
                          const Program& program);

}  // namespace rayspec
