// GLSL for every stage of a case, generated from its stage programs plus the
// shared pieces of shaders/. Binding numbers, the ray and record layouts and
// counter indices come from C++ tables (glsl/bindings.h,
// results/record_layout.h), never retyped in GLSL.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "case/case.h"
#include "plan/plan.h"

namespace rayspec {

struct GeneratedShader {
  Stage stage;
  std::string name;  // "raygen", "miss0", "hit1.any_hit", "callable2"
  std::string glsl;
  // (constant_id, 32-bit value) of the specialization constants this shader
  // sets (pipeline.specialize); the others keep their defaults.
  std::vector<std::pair<uint32_t, uint32_t>> specialization;
  // Raygen emitted as a compute shader (Pipeline::from_compute,
  // glsl/emit_compute.h): compiled as one, run by a compute pipeline.
  bool compute = false;
};

struct GeneratedGroup {
  std::optional<GeneratedShader> closest_hit, any_hit, intersection;
};

struct GeneratedPipeline {
  GeneratedShader raygen;
  std::vector<GeneratedShader> other_raygens;  // parallel to Pipeline::other_raygens
  uint32_t raygen_group = 0;                   // Pipeline::raygen_group
  std::vector<GeneratedShader> miss;
  std::vector<GeneratedGroup> hit_groups;  // parallel to Pipeline::hit_groups
  std::vector<GeneratedShader> callables;
};

GeneratedPipeline generateGlsl(const Case& c, const Plan& plan);

// Every stage of g: raygen, the other raygens, miss, each hit group's
// closest-hit, any-hit and intersection, callables.
std::vector<const GeneratedShader*> everyStage(const GeneratedPipeline& g);

}  // namespace rayspec
