#include <array>

#include "export/c_text.h"
#include "export/export_sections.h"
#include "glsl/emit_compute.h"
#include "vulkan/sbt_layout.h"

namespace rayspec {
namespace {

const char* stageBitName(const CompiledShader& shader) {
  if (shader.compute) return "VK_SHADER_STAGE_COMPUTE_BIT";
  switch (shader.stage) {
    case Stage::Raygen:
      return "VK_SHADER_STAGE_RAYGEN_BIT_KHR";
    case Stage::Miss:
      return "VK_SHADER_STAGE_MISS_BIT_KHR";
    case Stage::ClosestHit:
      return "VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR";
    case Stage::AnyHit:
      return "VK_SHADER_STAGE_ANY_HIT_BIT_KHR";
    case Stage::Intersection:
      return "VK_SHADER_STAGE_INTERSECTION_BIT_KHR";
    case Stage::Callable:
      return "VK_SHADER_STAGE_CALLABLE_BIT_KHR";
  }
  return "0";
}

// The stages in pipeline order, each one's GLSL as a comment above its SPIR-V.
struct Stages {
  std::string arrays, table;
  uint32_t count = 0;
  uint32_t add(const GeneratedShader& g, const CompiledShader& s) {
    const std::string name = "rs_spirv_" + std::to_string(count);
    arrays += "/* " + g.name + ": its GLSL, as rayspec generated it */\n" + cComment(g.glsl) +
              cWordArray(name, s.spirv);
    table += "  {" + std::string(stageBitName(s)) + ", " + name + ", sizeof " + name + "},\n";
    return count++;
  }
};

// The shader's index among the stages as C ("RS_NONE" where it has none).
std::string optionalStage(Stages& stages, const std::optional<GeneratedShader>& g,
                          const std::optional<CompiledShader>& s) {
  return g && s ? std::to_string(stages.add(*g, *s)) + "u" : std::string("RS_NONE");
}

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
         "\n#define RS_HIT_PADDING " + std::to_string(p.sbt_padding.hit) + "\n";
}

// The callable region's records (after sbtText's).
std::string callableSbtText(const Pipeline& p) {
  const std::vector<SbtRecord> callable = sbtCallableRecords(p);
  return recordArray("rs_callable_records", callable, sbtCallableGroup(p, 0)) +
         "#define RS_CALLABLE_RECORDS " + std::to_string(callable.size()) +
         "\n#define RS_CALLABLE_PADDING " + std::to_string(p.sbt_padding.callable) + "\n\n";
}

// The raygen groups' rows of rs_groups: the one the raygen record selects is
// `raygen`, the others in the case's order around it.
std::string raygenGroups(const Pipeline& p, const GeneratedPipeline& generated,
                         const CompiledPipeline& compiled, Stages& stages) {
  std::string groups;
  for (uint32_t r = 0; r < p.raygenGroupCount(); ++r) {
    const uint32_t other = r < compiled.raygen_group ? r : r - 1;
    groups +=
        generalGroup(r == compiled.raygen_group ? stages.add(generated.raygen, compiled.raygen)
                                                : stages.add(generated.other_raygens[other],
                                                             compiled.other_raygens[other]));
  }
  return groups;
}

// The hit groups' rows of rs_groups: triangles, or procedural with an intersection shader.
std::string hitGroups(const GeneratedPipeline& generated, const CompiledPipeline& compiled,
                      Stages& stages) {
  std::string groups;
  for (size_t i = 0; i < compiled.hit_groups.size(); ++i) {
    const CompiledGroup& g = compiled.hit_groups[i];
    const GeneratedGroup& gen = generated.hit_groups[i];
    const std::string chit = optionalStage(stages, gen.closest_hit, g.closest_hit);
    const std::string ahit = optionalStage(stages, gen.any_hit, g.any_hit);
    const std::string isect = optionalStage(stages, gen.intersection, g.intersection);
    groups += std::string("  {") +
              (g.intersection ? "VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR"
                              : "VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR") +
              ", RS_NONE, " + chit + ", " + ahit + ", " + isect + "},\n";
  }
  return groups;
}

// What the device must offer the stages: ray queries (VK_KHR_ray_query),
// a scalar shader record block (scalarBlockLayout).
std::string needsText(const Pipeline& p, const Plan& plan) {
  const bool ray_queries = p.ray_query || p.ray_query_in_hit || plan.ray_queries;
  return "#define RS_NEEDS_RAY_QUERY " + std::string(ray_queries ? "1" : "0") +
         "\n#define RS_NEEDS_SCALAR_LAYOUT " +
         (p.record_layout.declared() && p.record_layout.scalar ? "1" : "0") + "\n";
}

// Raygen run as a compute shader (Pipeline::from_compute): the one stage,
// the dispatch's group counts (computeGroups), and no ray tracing pipeline
// or SBT (their tables left empty).
std::string computeSection(const Case& c, const Plan& plan, const GeneratedPipeline& generated,
                           const CompiledPipeline& compiled) {
  Stages stages;
  stages.add(generated.raygen, compiled.raygen);
  const std::array<uint32_t, 3> groups = computeGroups(c.rays.launchSize());
  return "/* Raygen as a compute shader (pipeline.traces: ray_query_compute): SPIR-V as rayspec "
         "compiled it,\n   dispatched in groups of " +
         std::to_string(kComputeGroupSize) + "; no ray tracing pipeline, no SBT. */\n" +
         stages.arrays + "static const rs_shader rs_shaders[] = {\n" + stages.table + "};\n" +
         "static const rs_group rs_groups[] = {\n" + generalGroup(0) +
         "};\n#define RS_SHADER_COUNT 1\n#define RS_GROUP_COUNT 1\n#define RS_MAX_RECURSION 1u\n" +
         needsText(c.pipeline, plan) + "#define RS_COMPUTE 1\n#define RS_COMPUTE_GROUPS_X " +
         std::to_string(groups[0]) + "u\n#define RS_COMPUTE_GROUPS_Y " + std::to_string(groups[1]) +
         "u\n#define RS_COMPUTE_GROUPS_Z " + std::to_string(groups[2]) + "u\n" +
         "static const rs_record rs_raygen_record = {RS_NONE, 0u, {0}};\n" +
         recordArray("rs_miss_records", {}, 0) + recordArray("rs_hit_records", {}, 0) +
         recordArray("rs_callable_records", {}, 0) +
         "#define RS_MISS_RECORDS 0\n#define RS_HIT_RECORDS 0\n#define RS_CALLABLE_RECORDS 0\n"
         "#define RS_RECORD_DATA_BYTES 0\n#define RS_MISS_PADDING 0\n#define RS_HIT_PADDING 0\n"
         "#define RS_CALLABLE_PADDING 0\n\n";
}

}  // namespace

std::string pipelineSection(const Case& c, const Plan& plan, const GeneratedPipeline& generated,
                            const CompiledPipeline& compiled) {
  const Pipeline& p = c.pipeline;
  if (p.from_compute) return computeSection(c, plan, generated, compiled);
  Stages stages;
  std::string groups = raygenGroups(p, generated, compiled, stages);
  for (size_t i = 0; i < compiled.miss.size(); ++i)
    groups += generalGroup(stages.add(generated.miss[i], compiled.miss[i]));
  groups += hitGroups(generated, compiled, stages);
  for (size_t i = 0; i < compiled.callables.size(); ++i)
    groups += generalGroup(stages.add(generated.callables[i], compiled.callables[i]));
  return "/* The pipeline's stages: SPIR-V as rayspec compiled it. */\n" + stages.arrays +
         "static const rs_shader rs_shaders[] = {\n" + stages.table + "};\n" +
         "/* Shader groups: raygens, miss shaders, hit groups, callables (rayspec's group "
         "order). */\n" +
         "static const rs_group rs_groups[] = {\n" + groups + "};\n#define RS_SHADER_COUNT " +
         std::to_string(stages.count) + "\n#define RS_GROUP_COUNT " +
         std::to_string(sbtGroupCount(p)) + "\n#define RS_MAX_RECURSION " +
         std::to_string(p.max_recursion) + "u\n" + needsText(p, plan) +
         "#define RS_COMPUTE 0\n#define RS_COMPUTE_GROUPS_X 0u\n#define RS_COMPUTE_GROUPS_Y "
         "0u\n#define RS_COMPUTE_GROUPS_Z 0u\n\n" +
         sbtText(p) + callableSbtText(p);
}

}  // namespace rayspec
