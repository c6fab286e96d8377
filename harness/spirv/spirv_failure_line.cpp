// describeSpirvFailure: map a SPIRV-Tools message back to a GLSL line through
// the OpLine instructions of a debug build of the same shader.
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <spirv-tools/libspirv.hpp>

#include "spirv/glsl_error_lines.h"
#include "spirv/spirv_stage.h"

namespace rayspec {
namespace {

constexpr uint32_t kOpLine = 8;
constexpr uint32_t kHeaderWords = 5;

std::vector<uint32_t> debugBuild(const std::string& glsl, EShLanguage lang) {
  glslang::TShader shader(lang);
  const char* text = glsl.c_str();
  setUpShader(shader, &text, lang);
  const auto messages =
      static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules | EShMsgDebugInfo);
  if (!shader.parse(GetDefaultResources(), 460, false, messages)) return {};
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) return {};
  glslang::SpvOptions options;
  options.generateDebugInfo = true;
  std::vector<unsigned int> spirv;
  glslang::GlslangToSpv(*program.getIntermediate(lang), spirv, &options);
  return {spirv.begin(), spirv.end()};
}

// Last OpLine line at or before instruction `index` (0-based instruction count
// after the header); 0 when none.
uint32_t lineOfInstruction(const std::vector<uint32_t>& words, size_t index) {
  uint32_t line = 0;
  size_t w = kHeaderWords, n = 0;
  while (w < words.size() && n <= index) {
    const uint32_t count = words[w] >> 16, opcode = words[w] & 0xFFFF;
    if (count == 0) break;
    if (opcode == kOpLine && w + 2 < words.size()) line = words[w + 2];
    w += count;
    ++n;
  }
  return line;
}

}  // namespace

std::string describeSpirvFailure(const std::string& glsl, Stage stage, bool compute) {
  const std::vector<uint32_t> words = debugBuild(glsl, glslangStage(stage, compute));
  if (words.empty()) return {};
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_2);
  size_t index = 0;
  bool failed = false;
  tools.SetMessageConsumer(
      [&](spv_message_level_t, const char*, const spv_position_t& pos, const char*) {
        if (!failed) index = pos.index;
        failed = true;
      });
  if (tools.Validate(words) || !failed) return {};
  const uint32_t line = lineOfInstruction(words, index);
  if (line == 0) return {};
  return "  near GLSL line " + std::to_string(line) + " | " + glslLine(glsl, int(line)) + "\n";
}

}  // namespace rayspec
