// The glslang stage of a rayspec stage, and the one set-up of a glslang
// shader for rayspec's targets (Vulkan 1.2 client, SPIR-V 1.4, entry main).
#pragma once

#include <glslang/Public/ShaderLang.h>

#include "program/program.h"

namespace rayspec {

// `compute`: raygen run as a compute shader (glsl/emit_compute.h).
inline EShLanguage glslangStage(Stage s, bool compute = false) {
  if (compute) return EShLangCompute;
  switch (s) {
    case Stage::Raygen:
      return EShLangRayGen;
    case Stage::Miss:
      return EShLangMiss;
    case Stage::ClosestHit:
      return EShLangClosestHit;
    case Stage::AnyHit:
      return EShLangAnyHit;
    case Stage::Intersection:
      return EShLangIntersect;
    case Stage::Callable:
      return EShLangCallable;
  }
  return EShLangRayGen;
}

// `text` must outlive the shader's parse.
inline void setUpShader(glslang::TShader& shader, const char* const* text, EShLanguage lang) {
  shader.setStrings(text, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_4);
  shader.setEntryPoint("main");
}

}  // namespace rayspec
