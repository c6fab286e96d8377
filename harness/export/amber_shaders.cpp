// The stages of an exported Amber script: the device lines their SPIR-V
// needs and a SHADER ... SPIRV-HEX each, its GLSL in comments above it.
#include <cmath>
#include <cstdio>
#include <set>

#include "export/amber_sections.h"
#include "spirv/compile_glsl.h"

namespace rayspec {
namespace {

const char* amberType(Stage s) {
  switch (s) {
    case Stage::Raygen:
      return "ray_generation";
    case Stage::Miss:
      return "miss";
    case Stage::ClosestHit:
      return "closest_hit";
    case Stage::AnyHit:
      return "any_hit";
    case Stage::Intersection:
      return "intersection";
    case Stage::Callable:
      return "callable";
  }
  return "";
}

void addStage(std::vector<AmberStage>& out, const GeneratedShader& g, const CompiledShader& s) {
  out.push_back({amberType(g.stage), amberName(g.name), &g, &s});
}

void addOptional(std::vector<AmberStage>& out, const std::optional<GeneratedShader>& g,
                 const std::optional<CompiledShader>& s) {
  if (g && s) addStage(out, *g, *s);
}

// The SPIR-V's bytes as SPIRV-HEX reads them (each word's bytes, lowest
// first), lower case (no "END" inside), ending on the last digit: Amber's
// reader (ShaderCompiler::ParseHex) loops forever on blanks after the last
// byte, so END follows it directly.
std::string hexText(const std::vector<uint32_t>& words) {
  std::string out;
  char byte[4];
  for (size_t i = 0; i < words.size(); ++i) {
    for (int b = 0; b < 4; ++b) {
      std::snprintf(byte, sizeof byte, "%02x", (words[i] >> (8 * b)) & 0xFFu);
      out += byte;
      out += b == 3 && i % 8 == 7 ? "\n" : " ";
    }
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == '\n')) out.pop_back();
  return out;
}

}  // namespace

std::vector<AmberStage> amberStages(const GeneratedPipeline& generated,
                                    const CompiledPipeline& compiled) {
  std::vector<AmberStage> out;
  const size_t raygens = compiled.other_raygens.size() + 1;
  for (size_t r = 0; r < raygens; ++r) {
    if (r == compiled.raygen_group) {
      addStage(out, generated.raygen, compiled.raygen);
      continue;
    }
    const size_t other = r < compiled.raygen_group ? r : r - 1;
    addStage(out, generated.other_raygens[other], compiled.other_raygens[other]);
  }
  for (size_t i = 0; i < compiled.miss.size(); ++i)
    addStage(out, generated.miss[i], compiled.miss[i]);
  for (size_t i = 0; i < compiled.hit_groups.size(); ++i) {
    const GeneratedGroup& g = generated.hit_groups[i];
    const CompiledGroup& s = compiled.hit_groups[i];
    addOptional(out, g.closest_hit, s.closest_hit);
    addOptional(out, g.any_hit, s.any_hit);
    addOptional(out, g.intersection, s.intersection);
  }
  for (size_t i = 0; i < compiled.callables.size(); ++i)
    addStage(out, generated.callables[i], compiled.callables[i]);
  return out;
}

std::optional<std::string> amberCapabilityFeature(uint32_t capability) {
  switch (capability) {
    case 1:     // Shader
    case 61:    // GroupNonUniform (Vulkan 1.1)
    case 4479:  // RayTracingKHR: rayTracingPipeline, always requested
    case 5347:  // PhysicalStorageBufferAddresses: bufferDeviceAddress, always requested
      return "";
    case 9:
      return "Float16Int8Features.shaderFloat16";
    case 10:
      return "shaderFloat64";
    case 11:
      return "shaderInt64";
    case 22:
      return "shaderInt16";
    case 39:
      return "Float16Int8Features.shaderInt8";
    case 56:
      return "shaderStorageImageWriteWithoutFormat";
    case 4433:
      return "Storage16BitFeatures.storageBuffer16BitAccess";
    case 4448:
      return "Storage8BitFeatures.storageBuffer8BitAccess";
    case 5345:
      return "VulkanMemoryModelFeatures.vulkanMemoryModel";
    default:
      return std::nullopt;
  }
}

std::string amberDeviceLines(const std::vector<AmberStage>& stages) {
  std::set<std::string> features;
  for (const AmberStage& s : stages)
    for (uint32_t capability : declaredCapabilities(s.compiled->spirv))
      if (const std::optional<std::string> f = amberCapabilityFeature(capability); f && !f->empty())
        features.insert(*f);
  std::string out =
      "DEVICE_EXTENSION VK_KHR_acceleration_structure\n"
      "DEVICE_EXTENSION VK_KHR_ray_tracing_pipeline\n"
      "DEVICE_EXTENSION VK_KHR_buffer_device_address\n"
      "DEVICE_EXTENSION VK_KHR_deferred_host_operations\n"
      "DEVICE_FEATURE RayTracingPipelineFeaturesKHR.rayTracingPipeline\n"
      "DEVICE_FEATURE AccelerationStructureFeaturesKHR.accelerationStructure\n"
      "DEVICE_FEATURE BufferDeviceAddressFeatures.bufferDeviceAddress\n";
  for (const std::string& f : features) out += "DEVICE_FEATURE " + f + "\n";
  return out + "\n";
}

std::string amberShaders(const std::vector<AmberStage>& stages) {
  std::string out;
  for (const AmberStage& s : stages)
    out += "# ---- " + s.generated->name + ": its GLSL, as rayspec generated it ----\n" +
           amberComment(s.generated->glsl) + "SHADER " + s.type + " " + s.name + " SPIRV-HEX\n" +
           hexText(s.compiled->spirv) + "END\n\n";
  return out;
}

std::string amberName(const std::string& stage_name) {
  std::string out = stage_name;
  for (char& ch : out)
    if (ch == '.') ch = '_';
  return out;
}

std::string amberComment(const std::string& text) {
  std::string out;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    out += line.empty() ? "#\n" : "# " + line + "\n";
    start = end + 1;
  }
  return out;
}

std::string amberFloat(double v) {
  if (std::isnan(v)) return "nan";
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  std::string out = text;
  if (out.find('.') != std::string::npos) return out;
  const size_t e = out.find('e');
  return e == std::string::npos ? out + ".0" : out.insert(e, ".0");
}

}  // namespace rayspec
