#include "vulkan/stack_size.h"

#include <algorithm>

#include "vulkan/sbt_layout.h"

namespace rayspec {

VkDeviceSize pipelineStackSize(const ShaderStackSizes& s, uint32_t max_recursion,
                               uint32_t callable_depth) {
  const VkDeviceSize first_trace = std::max({s.closest_hit, s.miss, s.intersection + s.any_hit});
  const VkDeviceSize nested_trace = std::max(s.closest_hit, s.miss);
  return s.raygen + std::min<uint32_t>(1, max_recursion) * first_trace +
         (max_recursion > 0 ? max_recursion - 1 : 0) * nested_trace + callable_depth * s.callable;
}

ShaderStackSizes queryShaderStackSizes(const VulkanContext& ctx, const CompiledPipeline& compiled,
                                       const Pipeline& p, const RayTracingPipeline& pipeline) {
  auto size = [&](uint32_t case_group, VkShaderGroupShaderKHR shader) {
    const GroupSite& at = pipeline.group_site.at(case_group);
    return ctx.fn.getRayTracingShaderGroupStackSize(ctx.device, at.pipeline, at.index, shader);
  };
  auto raise = [](VkDeviceSize& to, VkDeviceSize v) {
    to = std::max(to, v);
  };
  ShaderStackSizes s;
  for (uint32_t g = 0; g < p.raygenGroupCount(); ++g)
    raise(s.raygen, size(g, VK_SHADER_GROUP_SHADER_GENERAL_KHR));
  for (uint32_t i = 0; i < compiled.miss.size(); ++i)
    raise(s.miss, size(sbtMissGroup(p, i), VK_SHADER_GROUP_SHADER_GENERAL_KHR));
  for (uint32_t i = 0; i < compiled.hit_groups.size(); ++i) {
    const CompiledGroup& g = compiled.hit_groups[i];
    const uint32_t id = sbtHitGroup(p, i);
    if (g.closest_hit) raise(s.closest_hit, size(id, VK_SHADER_GROUP_SHADER_CLOSEST_HIT_KHR));
    if (g.any_hit) raise(s.any_hit, size(id, VK_SHADER_GROUP_SHADER_ANY_HIT_KHR));
    if (g.intersection) raise(s.intersection, size(id, VK_SHADER_GROUP_SHADER_INTERSECTION_KHR));
  }
  for (uint32_t i = 0; i < compiled.callables.size(); ++i)
    raise(s.callable, size(sbtCallableGroup(p, i), VK_SHADER_GROUP_SHADER_GENERAL_KHR));
  return s;
}

}  // namespace rayspec
