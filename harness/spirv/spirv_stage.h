// The glslang stage of a rayspec stage.
#pragma once

#include <glslang/Public/ShaderLang.h>

#include "program/program.h"

namespace rayspec {

inline EShLanguage glslangStage(Stage s) {
  switch (s) {
    case Stage::Raygen: return EShLangRayGen;
    case Stage::Miss: return EShLangMiss;
    case Stage::ClosestHit: return EShLangClosestHit;
    case Stage::AnyHit: return EShLangAnyHit;
    case Stage::Intersection: return EShLangIntersect;
    case Stage::Callable: return EShLangCallable;
  }
  return EShLangRayGen;
}

}  // namespace rayspec
