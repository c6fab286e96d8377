// The GLSL building blocks of shaders/, embedded at build time
// (tools/embed_shaders.cmake): file name -> text.
#pragma once

#include <map>
#include <string>

namespace rayspec {
const std::map<std::string, std::string>& embeddedShaders();
}  // namespace rayspec
