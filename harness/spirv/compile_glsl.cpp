// GLSL -> SPIR-V: glslang as a library, SPIRV-Tools validation, and a cache
// keyed by a content hash (memory, plus <dir>/<hash>.spv when a folder is set).
#include "spirv/compile_glsl.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <spirv-tools/libspirv.hpp>

#include <algorithm>
#include <map>
#include <mutex>

#include "spirv/builtin_inputs.h"
#include "spirv/glsl_error_lines.h"
#include "spirv/spirv_cache.h"
#include "spirv/spirv_stage.h"

namespace rayspec {
namespace {

void initializeOnce() {
  static std::once_flag flag;
  std::call_once(flag, [] { glslang::InitializeProcess(); });
}

// glslang front end + SPIR-V back end. Fills words, or error (quoting lines).
void glslToSpirv(const std::string& glsl, EShLanguage lang, std::vector<uint32_t>& words,
                 std::string& error) {
  glslang::TShader shader(lang);
  const char* text = glsl.c_str();
  setUpShader(shader, &text, lang);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  if (!shader.parse(GetDefaultResources(), 460, false, messages)) {
    error = "glslang: " + quoteGlslLines(shader.getInfoLog(), glsl);
    return;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    error = "glslang link: " + quoteGlslLines(program.getInfoLog(), glsl);
    return;
  }
  glslang::SpvOptions options;
  options.validate = false;  // SPIRV-Tools runs below, with its messages kept
  spv::SpvBuildLogger logger;
  std::vector<unsigned int> spirv;
  glslang::GlslangToSpv(*program.getIntermediate(lang), spirv, &logger, &options);
  const std::string log = logger.getAllMessages();
  if (spirv.empty()) {
    error = "glslang SPIR-V back end produced nothing: " + log;
    return;
  }
  words.assign(spirv.begin(), spirv.end());
}

// SPIR-V capabilities RayTracingPositionFetchKHR (the vertex_position<i>
// built-ins, shaders/position_fetch.glsl) and RayQueryPositionFetchKHR (a
// ray query's, shaders/query_position_fetch.glsl).
constexpr uint32_t kPositionFetchCapabilities[] = {5336, 5391};

bool declaresCapability(const std::vector<uint32_t>& words, uint32_t capability) {
  const std::vector<uint32_t> declared = declaredCapabilities(words);
  return std::find(declared.begin(), declared.end(), capability) != declared.end();
}

// Whether the linked SPIRV-Tools knows position fetch: 2023.1 (Debian 12)
// predates it and rejects the capability as an invalid operand.
bool validatorKnowsPositionFetch() {
  static const bool known = [] {
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_2);
    tools.SetMessageConsumer(
        [](spv_message_level_t, const char*, const spv_position_t&, const char*) {});
    std::vector<uint32_t> w;
    return tools.Assemble("OpCapability RayTracingPositionFetchKHR\n", &w);
  }();
  return known;
}

// SPIRV-Tools validation for Vulkan 1.2, plus the checks of newer validators
// that Debian 12's lacks; returns the messages (empty = valid). A module
// with position fetch is left to the validation layer where SPIRV-Tools is
// too old to parse it (vulkan/case_support.cpp then requires a layer that
// knows the extension).
std::string validate(const std::vector<uint32_t>& words) {
  if (!validatorKnowsPositionFetch())
    for (uint32_t capability : kPositionFetchCapabilities)
      if (declaresCapability(words, capability)) return "";
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_2);
  std::string messages;
  tools.SetMessageConsumer(
      [&messages](spv_message_level_t, const char*, const spv_position_t& pos, const char* msg) {
        messages += "spirv-val (word " + std::to_string(pos.index) + "): " + msg + "\n";
      });
  if (tools.Validate(words)) return duplicateBuiltinInputs(words);
  if (messages.empty()) messages = "spirv-val: invalid module\n";
  return messages;
}

}  // namespace

SpirvResult compileGlsl(const std::string& glsl, Stage stage, bool compute) {
  SpirvResult result;
  const std::string key = spirvCacheKey(glsl, stage, compute);
  if (!key.empty() && spirvCacheLookup(key, result.words)) {
    result.from_cache = true;
    return result;
  }
  initializeOnce();
  glslToSpirv(glsl, glslangStage(stage, compute), result.words, result.error);
  if (!result.error.empty()) {
    result.words.clear();
    return result;
  }
  const std::string invalid = validate(result.words);
  if (!invalid.empty()) {
    result.error = invalid + describeSpirvFailure(glsl, stage, compute);
    result.words.clear();
    return result;
  }
  if (!key.empty()) spirvCacheStore(key, result.words);
  return result;
}

std::vector<uint32_t> declaredCapabilities(const std::vector<uint32_t>& words) {
  constexpr uint32_t kOpCapability = 17, kHeaderWords = 5;
  std::vector<uint32_t> out;
  for (size_t i = kHeaderWords; i < words.size();) {
    const uint32_t count = words[i] >> 16;
    if ((words[i] & 0xFFFF) == kOpCapability && count == 2 && i + 1 < words.size())
      out.push_back(words[i + 1]);
    i += count ? count : 1;
  }
  return out;
}

}  // namespace rayspec
