// The buffers, the ray tracing pipeline and the RUN of an exported Amber
// script: the bindings rayspec's engine makes (caseBindings), each backed by
// a BUFFER or the top level, the groups in rayspec's order, one shader
// binding table per region with the case's records.
#include <array>
#include <cctype>
#include <cstdio>
#include <set>

#include "export/amber_sections.h"
#include "glsl/bindings.h"
#include "results/record_layout.h"
#include "vulkan/case_buffers.h"
#include "vulkan/sbt_layout.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

std::string wordLines(const std::vector<uint32_t>& words) {
  std::string out;
  char word[16];
  for (size_t i = 0; i < words.size(); ++i) {
    std::snprintf(word, sizeof word, "0x%08x", words[i]);
    out += std::string(i % 8 ? " " : "  ") + word + (i % 8 == 7 ? "\n" : "");
  }
  if (!out.empty() && out.back() != '\n') out += "\n";
  return out;
}

std::string dataBuffer(const std::string& name, const std::vector<uint32_t>& words) {
  return "BUFFER " + name + " DATA_TYPE uint32 DATA\n" + wordLines(words) + "END\n";
}

std::string zeroBuffer(const std::string& name, uint64_t words) {
  return "BUFFER " + name + " DATA_TYPE uint32 SIZE " + std::to_string(words) + " FILL 0\n";
}

std::string bindBuffer(const std::string& name, uint32_t binding) {
  return "  BIND BUFFER " + name + " AS storage DESCRIPTOR_SET 0 BINDING " +
         std::to_string(binding) + "\n";
}

struct Backing {
  std::string buffers, binds;
};

// One binding's BUFFER and BIND; NotSupported for one the script does not back.
Result<void> backBinding(const Case& c, const Plan& plan, uint32_t b, Backing& out) {
  const uint64_t rays = uint64_t(c.rays.width) * c.rays.height;
  switch (b) {
    case kBindingTlas:
      out.binds += "  BIND ACCELERATION_STRUCTURE tlas DESCRIPTOR_SET 0 BINDING 0\n";
      return {};
    case kBindingRays:
      out.buffers += dataBuffer("rays", packRays(c.rays));
      break;
    case kBindingRecords:
      out.buffers += zeroBuffer("records", rays * recordWords()) +
                     "BUFFER records_as_float DATA_TYPE float SIZE " +
                     std::to_string(rays * recordWords()) + " FILL 0.0\n";
      break;
    case kBindingCounters:
      out.buffers += zeroBuffer("counters", plan.counters.size());
      break;
    case kBindingScene:
      out.buffers += dataBuffer("scene", packSceneData(c.scene));
      break;
    default:
      return notSupported("export: case uses descriptor binding " + std::to_string(b) +
                          " (no plan output backs it), not yet exported");
  }
  static const char* const kNames[] = {"tlas", "rays", "records", "counters", "scene"};
  out.binds += bindBuffer(kNames[b], b);
  return {};
}

std::string groupName(const CompiledShader& s) {
  return "group_" + amberName(s.name);
}

std::string hitGroupName(size_t i) {
  return "group_hit" + std::to_string(i);
}

// SHADER_GROUP lines in rayspec's group order.
std::string groupLines(const CompiledPipeline& compiled) {
  std::string out;
  const auto general = [&](const CompiledShader& s) {
    out += "  SHADER_GROUP " + groupName(s) + " " + amberName(s.name) + "\n";
  };
  for (size_t r = 0; r <= compiled.other_raygens.size(); ++r)
    general(r == compiled.raygen_group
                ? compiled.raygen
                : compiled.other_raygens[r < compiled.raygen_group ? r : r - 1]);
  for (const CompiledShader& m : compiled.miss) general(m);
  for (size_t i = 0; i < compiled.hit_groups.size(); ++i) {
    out += "  SHADER_GROUP " + hitGroupName(i);
    const CompiledGroup& g = compiled.hit_groups[i];
    for (const auto* s : {&g.closest_hit, &g.any_hit, &g.intersection})
      if (*s) out += " " + amberName((*s)->name);
    out += "\n";
  }
  for (const CompiledShader& k : compiled.callables) general(k);
  return out;
}

// One region's SHADER_BINDING_TABLE (records of a group each: amber_support.cpp
// refuses all-zero ones), and its part of the RUN line; nothing for no record.
void sbtTable(const std::string& region, const std::vector<std::string>& groups,
              std::string& tables, std::string& run) {
  if (groups.empty()) return;
  const std::string name = "sbt_" + region;
  tables += "  SHADER_BINDING_TABLE " + name + "\n";
  for (const std::string& g : groups) tables += "    " + g + "\n";
  tables += "  END\n";
  for (char ch : region) run += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  run += " " + name + " ";
}

std::vector<std::string> regionGroups(const std::vector<SbtRecord>& records,
                                      const std::vector<CompiledShader>& shaders) {
  std::vector<std::string> out;
  for (const SbtRecord& r : records) out.push_back(groupName(shaders[*r.group]));
  return out;
}

}  // namespace

Result<std::string> amberPipeline(const Case& c, const Plan& plan,
                                  const CompiledPipeline& compiled) {
  const Pipeline& p = c.pipeline;
  RAYSPEC_TRY(const std::set<uint32_t> bindings, caseBindings(plan, declaredBindings(compiled)));
  Backing backing;
  for (uint32_t b : bindings) RAYSPEC_TRY_VOID(backBinding(c, plan, b, backing));
  std::vector<std::string> hits;
  for (const SbtRecord& r : sbtHitRecords(p)) hits.push_back(hitGroupName(*r.group));
  std::string tables, run = "RUN pipeline ";
  sbtTable("raygen", {groupName(compiled.raygen)}, tables, run);
  sbtTable("miss", regionGroups(sbtMissRecords(p), compiled.miss), tables, run);
  sbtTable("hit", hits, tables, run);
  sbtTable("call", regionGroups(sbtCallableRecords(p), compiled.callables), tables, run);
  const std::array<uint32_t, 3> launch = c.rays.launchSize();
  return "# The rays as rayspec uploads them (" + std::to_string(kRayWords) +
         " words each), the record words, the counters.\n" + backing.buffers +
         "\nPIPELINE raytracing pipeline\n  MAX_RAY_RECURSION_DEPTH " +
         std::to_string(p.max_recursion) + "\n" + backing.binds + groupLines(compiled) + tables +
         "END\n\n" + run + std::to_string(launch[0]) + " " + std::to_string(launch[1]) + " " +
         std::to_string(launch[2]) + "\n\n";
}

}  // namespace rayspec
