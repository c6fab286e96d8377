#include "export/c_text.h"
#include "export/export_sections.h"
#include "vulkan/sbt_layout.h"

namespace rayspec {
namespace {

const char* stageBitName(Stage s) {
  switch (s) {
    case Stage::Raygen:
      return "VK_SHADER_STAGE_RAYGEN_BIT_KHR";
    case Stage::Miss:
      return "VK_SHADER_STAGE_MISS_BIT_KHR";
    case Stage::ClosestHit:
      return "VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR";
    default:
      return "0 /* a stage the export does not play */";
  }
}

// The stages in pipeline order, each one's GLSL as a comment above its SPIR-V.
struct Stages {
  std::string arrays, table;
  uint32_t count = 0;
  uint32_t add(const GeneratedShader& g, const CompiledShader& s) {
    const std::string name = "rs_spirv_" + std::to_string(count);
    arrays += "/* " + g.name + ": its GLSL, as rayspec generated it */\n" + cComment(g.glsl) +
              cWordArray(name, s.spirv);
    table += "  {" + std::string(stageBitName(s.stage)) + ", " + name + ", sizeof " + name + "},\n";
    return count++;
  }
};

std::string generalGroup(uint32_t shader) {
  return "  {VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR, " + std::to_string(shader) +
         "u, RS_NONE, RS_NONE, RS_NONE},\n";
}

// One SBT record: the group's index in the pipeline (RS_NONE: all zero), its data.
std::string recordEntry(const std::optional<uint32_t>& group, uint32_t first_group,
                        const std::vector<uint32_t>& data) {
  std::string words;
  for (size_t k = 0; k < data.size(); ++k) words += (k ? ", " : "") + std::to_string(data[k]) + "u";
  return "{" + (group ? std::to_string(first_group + *group) + "u" : std::string("RS_NONE")) +
         ", " + std::to_string(data.size()) + "u, {" + (words.empty() ? "0" : words) + "}}";
}

std::string recordArray(const std::string& name, const std::vector<SbtRecord>& records,
                        uint32_t first_group) {
  std::string out = "static const rs_record " + name + "[] = {\n";
  for (const SbtRecord& r : records)
    out += "  " + recordEntry(r.group, first_group, r.data) + ",\n";
  if (records.empty()) out += "  {RS_NONE, 0, {0}},\n";
  return out + "};\n";
}

std::string sbtText(const Pipeline& p) {
  const std::vector<SbtRecord> miss = sbtMissRecords(p), hit = sbtHitRecords(p);
  return "/* The shader binding table: each record's group (in the order above) and data. */\n"
         "static const rs_record rs_raygen_record = " +
         recordEntry(p.raygen_group, 0, p.raygen_data) + ";\n" +
         recordArray("rs_miss_records", miss, sbtMissGroup(p, 0)) +
         recordArray("rs_hit_records", hit, sbtHitGroup(p, 0)) + "#define RS_MISS_RECORDS " +
         std::to_string(miss.size()) + "\n#define RS_HIT_RECORDS " + std::to_string(hit.size()) +
         "\n#define RS_RECORD_DATA_BYTES " + std::to_string(p.sbt_record_data) +
         "\n#define RS_MISS_PADDING " + std::to_string(p.sbt_padding.miss) +
         "\n#define RS_HIT_PADDING " + std::to_string(p.sbt_padding.hit) + "\n\n";
}

}  // namespace

std::string pipelineSection(const Pipeline& p, const GeneratedPipeline& generated,
                            const CompiledPipeline& compiled) {
  Stages stages;
  std::string groups = generalGroup(stages.add(generated.raygen, compiled.raygen));
  for (size_t i = 0; i < compiled.miss.size(); ++i)
    groups += generalGroup(stages.add(generated.miss[i], compiled.miss[i]));
  for (size_t i = 0; i < compiled.hit_groups.size(); ++i) {
    const CompiledGroup& g = compiled.hit_groups[i];
    const std::string chit =
        g.closest_hit
            ? std::to_string(stages.add(*generated.hit_groups[i].closest_hit, *g.closest_hit)) + "u"
            : "RS_NONE";
    groups += "  {VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR, RS_NONE, " + chit +
              ", RS_NONE, RS_NONE},\n";
  }
  return "/* The pipeline's stages: SPIR-V as rayspec compiled it. */\n" + stages.arrays +
         "static const rs_shader rs_shaders[] = {\n" + stages.table + "};\n" +
         "/* Shader groups: raygen, miss shaders, hit groups (rayspec's group order). */\n" +
         "static const rs_group rs_groups[] = {\n" + groups + "};\n#define RS_SHADER_COUNT " +
         std::to_string(stages.count) + "\n#define RS_GROUP_COUNT " +
         std::to_string(sbtGroupCount(p)) + "\n#define RS_MAX_RECURSION " +
         std::to_string(p.max_recursion) + "\n\n" + sbtText(p);
}

}  // namespace rayspec
