// A minimal SPIR-V scan: the Binding decorations of descriptor set 0.
#include <map>

#include "vulkan/pipeline.h"

namespace rayspec {
namespace {

constexpr uint32_t kOpDecorate = 71;
constexpr uint32_t kDecorationBinding = 33;
constexpr uint32_t kDecorationDescriptorSet = 34;

void scan(const std::vector<uint32_t>& words, std::set<uint32_t>* out) {
  std::map<uint32_t, uint32_t> binding, set;  // result id -> value
  for (size_t i = 5; i < words.size();) {
    uint32_t count = words[i] >> 16, op = words[i] & 0xFFFF;
    if (count == 0) break;
    if (op == kOpDecorate && count >= 4) {
      if (words[i + 2] == kDecorationBinding) binding[words[i + 1]] = words[i + 3];
      if (words[i + 2] == kDecorationDescriptorSet) set[words[i + 1]] = words[i + 3];
    }
    i += count;
  }
  for (const auto& [id, b] : binding)
    if (set.count(id) == 0 || set[id] == 0) out->insert(b);
}

}  // namespace

std::set<uint32_t> declaredBindings(const CompiledPipeline& compiled) {
  std::set<uint32_t> out;
  scan(compiled.raygen.spirv, &out);
  for (const CompiledShader& s : compiled.other_raygens) scan(s.spirv, &out);
  for (const CompiledShader& s : compiled.miss) scan(s.spirv, &out);
  for (const CompiledGroup& g : compiled.hit_groups)
    for (const auto* s : {&g.closest_hit, &g.any_hit, &g.intersection})
      if (*s) scan((*s)->spirv, &out);
  for (const CompiledShader& s : compiled.callables) scan(s.spirv, &out);
  return out;
}

}  // namespace rayspec
