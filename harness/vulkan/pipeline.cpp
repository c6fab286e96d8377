#include "vulkan/pipeline.h"

#include <algorithm>
#include <chrono>
#include <deque>

#include "spirv/compile_glsl.h"
#include "vulkan/deferred_operation.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

Result<CompiledShader> compileOne(const GeneratedShader& g, StepCosts* costs) {
  const auto start = std::chrono::steady_clock::now();
  SpirvResult r = compileGlsl(g.glsl, g.stage, g.compute);
  if (costs)
    costs->add(r.from_cache ? CostStep::SpirvCacheHit : CostStep::SpirvCompile,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (r.words.empty())
    return errorOf(ErrorKind::ShaderCompile,
                   g.name + ": " + (r.error.empty() ? "no SPIR-V" : r.error));
  return CompiledShader{g.stage, g.name, std::move(r.words), g.specialization, g.compute};
}

VkShaderStageFlagBits vkStage(Stage s) {
  switch (s) {
    case Stage::Raygen:
      return VK_SHADER_STAGE_RAYGEN_BIT_KHR;
    case Stage::Miss:
      return VK_SHADER_STAGE_MISS_BIT_KHR;
    case Stage::ClosestHit:
      return VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR;
    case Stage::AnyHit:
      return VK_SHADER_STAGE_ANY_HIT_BIT_KHR;
    case Stage::Intersection:
      return VK_SHADER_STAGE_INTERSECTION_BIT_KHR;
    case Stage::Callable:
      return VK_SHADER_STAGE_CALLABLE_BIT_KHR;
  }
  return VK_SHADER_STAGE_RAYGEN_BIT_KHR;
}

// Shader modules and stage infos; the modules die with `local` once the
// pipeline exists.
class StageList {
 public:
  StageList(const VulkanContext& ctx, Cleanup& local) : ctx_(ctx), local_(local) {}
  // The stage's index, or the Device error.
  Result<uint32_t> add(const CompiledShader& s) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = s.spirv.size() * 4;
    info.pCode = s.spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    RAYSPEC_TRY_VOID(vkCheck(vkCreateShaderModule(ctx_.device, &info, nullptr, &module),
                             "vkCreateShaderModule"));
    VkDevice device = ctx_.device;
    local_.add([device, module] { vkDestroyShaderModule(device, module, nullptr); });
    VkPipelineShaderStageCreateInfo stage{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stage.stage = s.compute ? VK_SHADER_STAGE_COMPUTE_BIT : vkStage(s.stage);
    stage.module = module;
    stage.pName = "main";
    stage.pSpecializationInfo = specialization(s);
    stages_.push_back(stage);
    return static_cast<uint32_t>(stages_.size() - 1);
  }
  Result<uint32_t> add(const std::optional<CompiledShader>& s) {
    return s ? add(*s) : Result<uint32_t>(VK_SHADER_UNUSED_KHR);
  }
  const std::vector<VkPipelineShaderStageCreateInfo>& stages() const { return stages_; }

 private:
  // Each constant a 4-byte entry of the shader's own data; null when it sets none.
  const VkSpecializationInfo* specialization(const CompiledShader& s) {
    if (s.specialization.empty()) return nullptr;
    Specialization& sp = specializations_.emplace_back();
    for (const auto& [id, bits] : s.specialization) {
      sp.entries.push_back({id, static_cast<uint32_t>(4 * sp.data.size()), 4});
      sp.data.push_back(bits);
    }
    sp.info.mapEntryCount = static_cast<uint32_t>(sp.entries.size());
    sp.info.pMapEntries = sp.entries.data();
    sp.info.dataSize = 4 * sp.data.size();
    sp.info.pData = sp.data.data();
    return &sp.info;
  }

  struct Specialization {
    std::vector<VkSpecializationMapEntry> entries;
    std::vector<uint32_t> data;
    VkSpecializationInfo info{};
  };
  const VulkanContext& ctx_;
  Cleanup& local_;
  std::vector<VkPipelineShaderStageCreateInfo> stages_;
  std::deque<Specialization> specializations_;  // stable addresses
};

VkRayTracingShaderGroupCreateInfoKHR group(VkRayTracingShaderGroupTypeKHR type) {
  VkRayTracingShaderGroupCreateInfoKHR g{
      VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
  g.type = type;
  g.generalShader = g.closestHitShader = g.anyHitShader = g.intersectionShader =
      VK_SHADER_UNUSED_KHR;
  return g;
}

Result<VkRayTracingShaderGroupCreateInfoKHR> caseGroup(const CompiledPipeline& compiled,
                                                       uint32_t id, StageList& stages) {
  const uint32_t raygens = 1 + static_cast<uint32_t>(compiled.other_raygens.size());
  const uint32_t miss = static_cast<uint32_t>(compiled.miss.size());
  const uint32_t hits = static_cast<uint32_t>(compiled.hit_groups.size());
  auto general = [&](const CompiledShader& s) -> Result<VkRayTracingShaderGroupCreateInfoKHR> {
    VkRayTracingShaderGroupCreateInfoKHR g = group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR);
    RAYSPEC_TRY(g.generalShader, stages.add(s));
    return g;
  };
  const uint32_t selected = compiled.raygen_group;
  if (id < raygens)
    return general(id == selected ? compiled.raygen
                                  : compiled.other_raygens[id < selected ? id : id - 1]);
  id -= raygens - 1;  // now 1 + the index among miss, hit groups, callables
  if (id <= miss) return general(compiled.miss[id - 1]);
  if (id <= miss + hits) {
    const CompiledGroup& cg = compiled.hit_groups[id - 1 - miss];
    VkRayTracingShaderGroupCreateInfoKHR g =
        group(cg.intersection ? VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR
                              : VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR);
    RAYSPEC_TRY(g.closestHitShader, stages.add(cg.closest_hit));
    RAYSPEC_TRY(g.anyHitShader, stages.add(cg.any_hit));
    RAYSPEC_TRY(g.intersectionShader, stages.add(cg.intersection));
    return g;
  }
  return general(compiled.callables.at(id - 1 - miss - hits));
}

}  // namespace

Result<CompiledPipeline> compilePipeline(const GeneratedPipeline& generated, StepCosts* costs) {
  CompiledPipeline out;
  RAYSPEC_TRY(out.raygen, compileOne(generated.raygen, costs));
  out.raygen_group = generated.raygen_group;
  for (const GeneratedShader& s : generated.other_raygens) {
    RAYSPEC_TRY(out.other_raygens.emplace_back(), compileOne(s, costs));
  }
  for (const GeneratedShader& s : generated.miss) {
    RAYSPEC_TRY(out.miss.emplace_back(), compileOne(s, costs));
  }
  for (const GeneratedGroup& g : generated.hit_groups) {
    CompiledGroup& cg = out.hit_groups.emplace_back();
    if (g.closest_hit) {
      RAYSPEC_TRY(cg.closest_hit, compileOne(*g.closest_hit, costs));
    }
    if (g.any_hit) {
      RAYSPEC_TRY(cg.any_hit, compileOne(*g.any_hit, costs));
    }
    if (g.intersection) {
      RAYSPEC_TRY(cg.intersection, compileOne(*g.intersection, costs));
    }
  }
  for (const GeneratedShader& s : generated.callables) {
    RAYSPEC_TRY(out.callables.emplace_back(), compileOne(s, costs));
  }
  return out;
}

Result<VkPipelineLayout> createPipelineLayout(const VulkanContext& ctx,
                                              VkDescriptorSetLayout set_layout, Cleanup& cleanup) {
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = set_layout ? 1 : 0;  // none: pipeline.layout: empty
  info.pSetLayouts = set_layout ? &set_layout : nullptr;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(vkCheck(vkCreatePipelineLayout(ctx.device, &info, nullptr, &layout),
                           "vkCreatePipelineLayout"));
  VkDevice device = ctx.device;
  cleanup.add([device, layout] { vkDestroyPipelineLayout(device, layout, nullptr); });
  return layout;
}

Result<VkPipeline> createComputePipeline(const VulkanContext& ctx, const CompiledShader& shader,
                                         VkPipelineLayout layout, Cleanup& cleanup) {
  Cleanup modules;
  StageList stages(ctx, modules);
  RAYSPEC_TRY_VOID(stages.add(shader));
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = stages.stages().front();
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  RAYSPEC_TRY_VOID(
      vkCheck(vkCreateComputePipelines(ctx.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
              "vkCreateComputePipelines"));
  VkDevice device = ctx.device;
  cleanup.add([device, pipeline] { vkDestroyPipeline(device, pipeline, nullptr); });
  return pipeline;
}

Result<VkPipeline> createPipelineObject(const VulkanContext& ctx, const CompiledPipeline& compiled,
                                        const PipelinePart& part, Cleanup& cleanup) {
  Cleanup modules;
  StageList stages(ctx, modules);
  std::vector<VkRayTracingShaderGroupCreateInfoKHR> groups;
  for (uint32_t id : part.groups) {
    RAYSPEC_TRY(groups.emplace_back(), caseGroup(compiled, id, stages));
  }

  VkRayTracingPipelineCreateInfoKHR info{VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
  info.flags = part.flags;
  info.stageCount = static_cast<uint32_t>(stages.stages().size());
  info.pStages = stages.stages().data();
  info.groupCount = static_cast<uint32_t>(groups.size());
  info.pGroups = groups.data();
  info.maxPipelineRayRecursionDepth = part.max_recursion;
  info.layout = part.layout;
  VkPipelineLibraryCreateInfoKHR libraries{VK_STRUCTURE_TYPE_PIPELINE_LIBRARY_CREATE_INFO_KHR};
  VkRayTracingPipelineInterfaceCreateInfoKHR interface {
    VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_INTERFACE_CREATE_INFO_KHR
  };
  if (part.linked) {
    libraries.libraryCount = static_cast<uint32_t>(part.libraries.size());
    libraries.pLibraries = part.libraries.data();
    info.pLibraryInfo = &libraries;
    interface.maxPipelineRayPayloadSize = part.max_payload_bytes;
    interface.maxPipelineRayHitAttributeSize = ctx.rt_props.maxRayHitAttributeSize;
    info.pLibraryInterface = &interface;
  }
  const VkDynamicState stack_size = VK_DYNAMIC_STATE_RAY_TRACING_PIPELINE_STACK_SIZE_KHR;
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  if (part.dynamic_stack_size) {
    dynamic.dynamicStateCount = 1;
    dynamic.pDynamicStates = &stack_size;
    info.pDynamicState = &dynamic;
  }
  VkPipeline pipeline = VK_NULL_HANDLE;
  const auto create = [&](VkDeferredOperationKHR op) {
    return ctx.fn.createRayTracingPipelines(ctx.device, op, ctx.pipeline_cache, 1, &info, nullptr,
                                            &pipeline);
  };
  const char* what = "vkCreateRayTracingPipelinesKHR";
  if (part.deferred_threads) {
    RAYSPEC_TRY(pipeline,
                createDeferred(ctx, *part.deferred_threads, what, create, pipeline, cleanup));
  } else {
    RAYSPEC_TRY_VOID(vkCall(what, [&] { return create(VK_NULL_HANDLE); }));
  }
  VkDevice device = ctx.device;
  cleanup.add([device, pipeline] { vkDestroyPipeline(device, pipeline, nullptr); });
  return pipeline;
}

Result<std::vector<uint8_t>> groupHandles(const VulkanContext& ctx,
                                          const RayTracingPipeline& pipeline) {
  const size_t size = ctx.rt_props.shaderGroupHandleSize;
  const uint32_t count = static_cast<uint32_t>(pipeline.group_index.size());
  std::vector<uint8_t> linked(count * size);
  RAYSPEC_TRY_VOID(
      vkCheck(ctx.fn.getRayTracingShaderGroupHandles(ctx.device, pipeline.pipeline, 0, count,
                                                     linked.size(), linked.data()),
              "vkGetRayTracingShaderGroupHandlesKHR"));
  std::vector<uint8_t> handles(linked.size());
  for (uint32_t g = 0; g < count; ++g)
    std::copy_n(&linked[pipeline.group_index[g] * size], size, &handles[g * size]);
  return handles;
}

}  // namespace rayspec
