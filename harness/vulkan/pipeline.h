// The ray tracing pipeline of a case: SPIR-V of every generated stage, shader
// groups in the order of sbt_layout.h (raygen, miss..., hit groups...,
// callables...), maxPipelineRayRecursionDepth = the case's max_recursion.
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "case/case.h"
#include "glsl/generate_glsl.h"
#include "results/step_cost.h"
#include "vulkan/cleanup.h"
#include "vulkan/context.h"

namespace rayspec {

struct CompiledShader {
  Stage stage = Stage::Raygen;
  std::string name;
  std::vector<uint32_t> spirv;
  std::vector<std::pair<uint32_t, uint32_t>> specialization;  // GeneratedShader's
  bool compute = false;                                       // GeneratedShader's
};

struct CompiledGroup {
  std::optional<CompiledShader> closest_hit, any_hit, intersection;
};

struct CompiledPipeline {
  CompiledShader raygen;
  std::vector<CompiledShader> other_raygens;  // parallel to Pipeline::other_raygens
  uint32_t raygen_group = 0;                  // Pipeline::raygen_group
  std::vector<CompiledShader> miss;
  std::vector<CompiledGroup> hit_groups;
  std::vector<CompiledShader> callables;
};

// compileGlsl on every stage, or the ShaderCompile error of a generated stage
// glslang or SPIRV-Tools rejected ("<name>: <message>"). The time of each
// stage goes to costs (when given): spirv_cache_hit or spirv_compile.
Result<CompiledPipeline> compilePipeline(const GeneratedPipeline& generated,
                                         StepCosts* costs = nullptr);

// Binding numbers (descriptor set 0) the SPIR-V of any stage declares.
std::set<uint32_t> declaredBindings(const CompiledPipeline& compiled);

// A layout of set_layout as set 0, or of no set at all for VK_NULL_HANDLE
// (pipeline.layout: empty); no push constant either way.
Result<VkPipelineLayout> createPipelineLayout(const VulkanContext& ctx,
                                              VkDescriptorSetLayout set_layout, Cleanup& cleanup);

// The interface a pipeline linked from libraries declares
// (maxPipelineRayPayloadSize, the same for every library and the linked
// pipeline): the case's largest payload or callable data type of
// shaders/payload.glsl (RsPayload 24 bytes, RsCallData 48, each with its
// type's words: pipeline.payloads, pipeline.callable_data).
uint32_t interfacePayloadBytes(const Pipeline& p);

// Raygen run as a compute shader (Pipeline::from_compute): its compute
// pipeline, or the Device error.
Result<VkPipeline> createComputePipeline(const VulkanContext& ctx, const CompiledShader& shader,
                                         VkPipelineLayout layout, Cleanup& cleanup);

// One vkCreateRayTracingPipelinesKHR call: the case groups `groups` (ids in
// sbt_layout.h's group order) in that order, linking `libraries` when `linked`
// (then with the library interface); or the Device error.
struct PipelinePart {
  std::vector<uint32_t> groups;
  std::vector<VkPipeline> libraries;
  bool linked = false;
  VkPipelineCreateFlags flags = 0;
  uint32_t max_recursion = 1;
  uint32_t max_payload_bytes = 0;  // the library interface's (interfacePayloadBytes)
  VkPipelineLayout layout = VK_NULL_HANDLE;
  bool dynamic_stack_size = false;  // VK_DYNAMIC_STATE_RAY_TRACING_PIPELINE_STACK_SIZE_KHR
  // Set: created through a deferred operation joined by this many threads
  // (Pipeline::deferred_threads; vulkan/deferred_operation.h).
  std::optional<uint32_t> deferred_threads;
};
Result<VkPipeline> createPipelineObject(const VulkanContext& ctx, const CompiledPipeline& compiled,
                                        const PipelinePart& part, Cleanup& cleanup);

// The case's pipeline (pipeline_libraries.cpp): one pipeline, or linked from
// the case's pipeline libraries (R-LIBRARY), each a library pipeline of its
// own groups and libraries. group_index[g] is where case group g sits in the
// linked pipeline: its own groups first, then each library's in the order
// linked, recursively (the specification's order of a linked pipeline's
// groups). Or the Device error.
// group_site[g] is the pipeline object that creates case group g (the linked
// pipeline or one of its libraries) and its index among that object's own
// groups: vkGetRayTracingShaderGroupStackSizeKHR counts only those.
struct GroupSite {
  VkPipeline pipeline = VK_NULL_HANDLE;
  uint32_t index = 0;
};
struct RayTracingPipeline {
  VkPipeline pipeline = VK_NULL_HANDLE;
  std::vector<uint32_t> group_index;
  std::vector<GroupSite> group_site;
};
Result<RayTracingPipeline> createRayTracingPipeline(const VulkanContext& ctx,
                                                    const CompiledPipeline& compiled,
                                                    const Pipeline& p, VkPipelineLayout layout,
                                                    Cleanup& cleanup);

// The group handles in the case's group order, sbtGroupCount *
// shaderGroupHandleSize bytes (read from the linked pipeline through
// group_index).
Result<std::vector<uint8_t>> groupHandles(const VulkanContext& ctx,
                                          const RayTracingPipeline& pipeline);

}  // namespace rayspec
