#include "export/export_c.h"

#include "export/c_text.h"
#include "export/expected_values.h"
#include "export/export_sections.h"
#include "export/export_support.h"
#include "glsl/generate_glsl.h"
#include "vulkan/pipeline.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

constexpr const char* kDataMarker = "/* RAYSPEC_CASE_DATA */";

// The header's line for a planted layout fault (none: "").
std::string faultLine(LayoutFault layout) {
  if (layout == LayoutFault::None) return "";
  return std::string(
             " * Planted fault (a test of rayspec's, standing in for a wrong driver): the builds\n"
             " * are given their inputs as the fault `") +
         nameOf(layout) +
         "` misreads them, so a correct device\n"
         " * FAILs; `rayspec export` of the case writes it without.\n";
}

// The file's opening comment: what it is, how to build and run it.
std::string header(const Case& c, LayoutFault layout) {
  return "/* rayspec export of case " + c.name + " (" + c.file +
         ")\n"
         " * Rules it checks: " +
         caseRulesText(c) +
         "\n"
         " * A standalone reproducer: the case's scene, pipeline (SPIR-V, with the GLSL it was\n"
         " * compiled from in comments), shader binding table and rays, traced on a Vulkan\n"
         " * device, and each result compared with what rayspec's reference model expects.\n" +
         faultLine(layout) +
         " *\n"
         " * Build: " +
         kReproducerBuildLine +
         "   (add -DRAYSPEC_VALIDATION for the\n"
         " *        validation layer, when installed)\n"
         " * Run:   " +
         kReproducerRunLine +
         "   (DEVICE: an index, or a part of the device's name;\n"
         " *        default: the first device with VK_KHR_ray_tracing_pipeline)\n"
         " * Exit:  0 PASS; 0 too for a QualityWarning, as rayspec (a \"should\" broken, no\n"
         " *        failure: a ray on a shared edge or vertex that leaked or hit twice,\n"
         " *        R-WATERTIGHT), a WARNING line per ray (the first 8) and a last line\n"
         " *        starting \"QualityWarning:\" where PASS would stand; 1 FAIL, printing the\n"
         " *        rule, the ray, the field, the expected and the observed value;\n"
         " *        77 NotSupported, naming the missing feature; 2 a Vulkan call failed.\n"
         " */\n";
}

}  // namespace

Result<std::string> exportCaseAsC(const Case& c, const Plan& plan, const Results& model,
                                  LayoutFault layout) {
  if (const std::string feature = unexportedFeature(c, plan, model); !feature.empty())
    return notSupported("export: case uses " + feature + ", not yet exported");
  const GeneratedPipeline generated = generateGlsl(c, plan);
  RAYSPEC_TRY(const CompiledPipeline compiled, compilePipeline(generated));
  RAYSPEC_TRY(const std::string launch, launchSection(c, plan, compiled));
  const std::string data = "#define RS_CASE_NAME " + cString(c.name) + "\n\n" +
                           sceneSection(c.scene, layout) +
                           pipelineSection(c, plan, generated, compiled) + launch +
                           expectationsSection(c, plan, model) + imagesSection(c, plan, model);
  std::string player = exportPlayerSource();
  const size_t at = player.find(kDataMarker);
  if (at == std::string::npos)
    return errorOf(ErrorKind::Harness, "export: the embedded player has no data marker");
  player.replace(at, std::string(kDataMarker).size(), data);
  return header(c, layout) + player;
}

}  // namespace rayspec
