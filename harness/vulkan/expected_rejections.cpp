#include "vulkan/expected_rejections.h"

#include "glsl/generate_glsl.h"
#include "spirv/compile_glsl.h"

namespace rayspec {
namespace {

const GeneratedShader* shaderNamed(const GeneratedPipeline& g, const std::string& name) {
  for (const GeneratedShader* s : everyStage(g))
    if (s->name == name) return s;
  return nullptr;
}

// Whether glslang refused `shader` for the interface its program uses.
bool rejectedForUse(const GeneratedShader& shader, const ExpectedRejection& e) {
  const SpirvResult r = compileGlsl(shader.glsl, shader.stage);
  if (r.error.empty() || e.uses.empty()) return false;
  const std::string said = "'" + e.uses.front().qualifier + "' : not supported in this stage";
  return r.error.find(said) != std::string::npos;
}

}  // namespace

void compileExpectedRejections(const Case& c, const Plan& plan, Results& r) {
  const GeneratedPipeline g = generateGlsl(c, plan);
  for (const ExpectedRejection& e : c.expected_rejections)
    if (const GeneratedShader* s = shaderNamed(g, e.shader); s && rejectedForUse(*s, e))
      r.rejected.push_back(e.shader);
}

}  // namespace rayspec
