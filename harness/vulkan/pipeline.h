// The ray tracing pipeline of a case: SPIR-V of every generated stage, shader
// groups in the order of sbt_layout.h (raygen, miss..., hit groups...,
// callables...), maxPipelineRayRecursionDepth = the case's max_recursion.
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "glsl/generate_glsl.h"
#include "results/step_cost.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"

namespace rayspec {

// A generated stage glslang or SPIRV-Tools rejected; what() = "<name>: <message>".
struct ShaderCompileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct CompiledShader {
  Stage stage = Stage::Raygen;
  std::string name;
  std::vector<uint32_t> spirv;
};

struct CompiledGroup {
  std::optional<CompiledShader> closest_hit, any_hit, intersection;
};

struct CompiledPipeline {
  CompiledShader raygen;
  std::vector<CompiledShader> miss;
  std::vector<CompiledGroup> hit_groups;
  std::vector<CompiledShader> callables;
};

// compileGlsl on every stage; throws ShaderCompileError. The time of each
// stage goes to costs (when given): spirv_cache_hit or spirv_compile.
CompiledPipeline compilePipeline(const GeneratedPipeline& generated, StepCosts* costs = nullptr);

// Binding numbers (descriptor set 0) the SPIR-V of any stage declares.
std::set<uint32_t> declaredBindings(const CompiledPipeline& compiled);

VkPipelineLayout createPipelineLayout(const VulkanContext& ctx, VkDescriptorSetLayout set_layout,
                                      Cleanup& cleanup);

// Throws VulkanError.
VkPipeline createRayTracingPipeline(const VulkanContext& ctx, const CompiledPipeline& compiled,
                                    VkPipelineLayout layout, uint32_t max_recursion,
                                    VkPipelineCreateFlags flags, Cleanup& cleanup);

// The group handles, sbtGroupCount * shaderGroupHandleSize bytes.
std::vector<uint8_t> groupHandles(const VulkanContext& ctx, VkPipeline pipeline,
                                  uint32_t group_count);

}  // namespace rayspec
