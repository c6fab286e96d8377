// The parts of an exported Amber script (internal to export/, export_amber.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/result.h"
#include "case/case.h"
#include "glsl/generate_glsl.h"
#include "plan/plan.h"
#include "results/results.h"
#include "vulkan/pipeline.h"

namespace rayspec {

// "" when the subset can express the case; else what it cannot (the C
// export's refusals first, by unexportedFeature), as "export: case uses X,
// ..." whole.
std::string amberRefusal(const Case& c, const Plan& plan, const Results& model);
// One stage as the script declares it: its SHADER type and name, its GLSL
// and SPIR-V; in rayspec's group order (raygens, miss, hit groups' stages,
// callables).
struct AmberStage {
  const char* type;  // ray_generation, miss, closest_hit, any_hit, intersection, callable
  std::string name;  // amberName of the stage's
  const GeneratedShader* generated;
  const CompiledShader* compiled;
};
std::vector<AmberStage> amberStages(const GeneratedPipeline& generated,
                                    const CompiledPipeline& compiled);

// The same for the stages as the script carries them: a shader record read,
// a SPIR-V capability no DEVICE_FEATURE of Amber's allows (amberCapabilityFeature).
std::string amberStageRefusal(const std::vector<AmberStage>& stages);

// DEVICE_EXTENSION and DEVICE_FEATURE lines: ray tracing, and what the
// stages' SPIR-V capabilities need (amberCapabilityFeature).
std::string amberDeviceLines(const std::vector<AmberStage>& stages);
// The feature a SPIR-V capability needs, as a DEVICE_FEATURE name ("" for
// none); nullopt where Amber enables none that would allow it.
std::optional<std::string> amberCapabilityFeature(uint32_t capability);

// Every stage as SHADER ... SPIRV-HEX, its GLSL in comments above it.
std::string amberShaders(const std::vector<AmberStage>& stages);
// The bottom levels and the top level.
std::string amberScene(const Scene& scene);
// The buffers, the ray tracing pipeline (bindings, groups, shader binding
// tables) and the RUN; NotSupported for a binding the script does not back.
Result<std::string> amberPipeline(const Case& c, const Plan& plan,
                                  const CompiledPipeline& compiled);
// The EXPECT lines of every judged ray's record and of every counter.
std::string amberExpectations(const Case& c, const Plan& plan, const Results& model);

// A number as Amber reads a float (with a '.', or nan), exactly: a float's
// or a double's value parsed back to the same bits.
std::string amberFloat(double v);
// text as '#' comment lines.
std::string amberComment(const std::string& text);
// The name a stage has in the script ("hit1.any_hit": hit1_any_hit).
std::string amberName(const std::string& stage_name);

}  // namespace rayspec
