#include "export/c_text.h"
#include "export/export_sections.h"
#include "glsl/bindings.h"
#include "vulkan/case_buffers.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

// The player's kind of a binding, or "" for one it does not back.
std::string bindingKind(const Plan& plan, uint32_t binding) {
  if (binding >= kBindingFirstImage && binding - kBindingFirstImage < plan.images.size())
    return "RS_BIND_IMAGE";
  switch (binding) {
    case kBindingTlas:
      return "RS_BIND_TLAS";
    case kBindingRays:
      return "RS_BIND_RAYS";
    case kBindingRecords:
      return "RS_BIND_RECORDS";
    case kBindingCounters:
      return "RS_BIND_COUNTERS";
    case kBindingScene:
    case kBindingSbtTables:
      return "RS_BIND_WORDS";
    default:
      return "";
  }
}

// A binding's fixed words as the engine uploads them (case_buffers.cpp),
// their array into `arrays`; "NULL, 0" for a binding of another kind.
std::string wordsOf(const Case& c, uint32_t binding, std::string& arrays) {
  if (binding != kBindingScene && binding != kBindingSbtTables) return "NULL, 0";
  const std::string name = "rs_binding" + std::to_string(binding) + "_words";
  const std::vector<uint32_t> words =
      binding == kBindingScene ? packSceneData(c.scene) : packSbtTables(c.pipeline).words;
  arrays += cWordArray(name, words);
  return name + ", sizeof " + name;
}

}  // namespace

Result<std::string> launchSection(const Case& c, const Plan& plan,
                                  const CompiledPipeline& compiled) {
  RAYSPEC_TRY(const std::set<uint32_t> bindings, caseBindings(plan, declaredBindings(compiled)));
  std::string arrays, table;
  for (uint32_t b : bindings) {
    const std::string kind = bindingKind(plan, b);
    if (kind.empty())
      return notSupported("export: case uses descriptor binding " + std::to_string(b) +
                          " (no plan output backs it), not yet exported");
    table += "  {" + std::to_string(b) + ", " + kind + ", " + wordsOf(c, b, arrays) + "},\n";
  }
  const std::array<uint32_t, 3> launch = c.rays.launchSize();
  return "/* The rays as rayspec uploads them (" + std::to_string(kRayWords) +
         " words each), the launch, the descriptor bindings. */\n" +
         cWordArray("rs_rays", packRays(c.rays)) + "#define RS_LAUNCH_WIDTH " +
         std::to_string(launch[0]) + "u\n#define RS_LAUNCH_HEIGHT " + std::to_string(launch[1]) +
         "u\n#define RS_LAUNCH_DEPTH " + std::to_string(launch[2]) + "u\n#define RS_RAY_COUNT " +
         std::to_string(uint64_t(c.rays.width) * c.rays.height) + "u\n" + arrays +
         "static const rs_binding rs_bindings[] = {\n" + table + "};\n#define RS_BINDING_COUNT " +
         std::to_string(bindings.size()) + "u\n\n";
}

}  // namespace rayspec
