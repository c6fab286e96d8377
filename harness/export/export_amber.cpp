#include "export/export_amber.h"

#include "export/amber_sections.h"
#include "export/expected_values.h"
#include "glsl/generate_glsl.h"
#include "vulkan/pipeline.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

// The script's opening comment: what it is, how it differs from rayspec's
// own run, how to run it.
std::string scriptHeader(const Case& c) {
  return "#!amber\n"
         "# rayspec export of case " +
         c.name + " (" + c.file +
         ")\n"
         "# Rules it checks: " +
         caseRulesText(c) +
         "\n"
         "# The case's scene, pipeline (SPIR-V as rayspec compiled it, its GLSL in comments\n"
         "# above each SHADER), shader binding tables and rays, traced once; every record word\n"
         "# and counter rayspec's judge compares is held by an EXPECT to what rayspec's\n"
         "# reference model expects (floats within the field's tolerance on that ray).\n"
         "# As rayspec runs it but: the record words are bound as a storage buffer (rayspec\n"
         "# reaches them through a device address, which a script cannot give a shader), and\n"
         "# Amber builds every acceleration structure without build flags (rayspec's:\n"
         "# scene.build.flags, performance hints here).\n"
         "#\n"
         "# Run:  " +
         kAmberRunLine +
         "   (-d: without the validation layer; -D ID: another device)\n"
         "# Exit: 0 every EXPECT holds; 1 one fails (Amber names the line, the index and the\n"
         "#       observed value) or a step failed; the line above each ray's EXPECTs names\n"
         "#       its fields and the rule each checks.\n\n";
}

}  // namespace

Result<std::string> exportCaseAsAmber(const Case& c, const Plan& plan, const Results& model) {
  if (const std::string refusal = amberRefusal(c, plan, model); !refusal.empty())
    return notSupported(refusal);
  Plan bound = plan;
  bound.records_bound = true;  // a script cannot hand a shader an address
  const GeneratedPipeline generated = generateGlsl(c, bound);
  RAYSPEC_TRY(const CompiledPipeline compiled, compilePipeline(generated));
  const std::vector<AmberStage> stages = amberStages(generated, compiled);
  if (const std::string refusal = amberStageRefusal(stages); !refusal.empty())
    return notSupported(refusal);
  RAYSPEC_TRY(const std::string pipeline, amberPipeline(c, plan, compiled));
  return scriptHeader(c) + amberDeviceLines(stages) + amberShaders(stages) + amberScene(c.scene) +
         pipeline + amberExpectations(c, plan, model);
}

}  // namespace rayspec
