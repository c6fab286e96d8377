#include "vulkan/run_case.h"

#include <algorithm>

#include "case/flag_names.h"
#include "glsl/generate_glsl.h"
#include "vulkan/address_table.h"
#include "vulkan/case_buffers.h"
#include "vulkan/commands.h"
#include "vulkan/descriptors.h"
#include "vulkan/expected_rejections.h"
#include "vulkan/library_group_handles.h"
#include "vulkan/pipeline.h"
#include "vulkan/sbt_buffer.h"
#include "vulkan/scene_builder.h"
#include "vulkan/stack_size.h"
#include "vulkan/trace.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

// Waits for the device before destroying the case's objects, on every path.
struct CaseScope {
  CaseScope(VkDevice d, StepCosts& c) : device(d), costs(c) {}
  ~CaseScope() {
    StepTimer time(costs, CostStep::CaseCleanup);
    vkDeviceWaitIdle(device);
    cleanup.run();
  }
  VkDevice device;
  StepCosts& costs;
  Cleanup cleanup;
};

// What the launch binds: a ray tracing pipeline with its SBT (and stack
// size), or raygen's compute pipeline (no SBT).
struct Launch {
  TraceBinding bound;
  SbtBuffer sbt;
};

// The case's ray tracing pipeline and SBT; the library handles compared where
// the context asks for it.
Result<Launch> rayTracingLaunch(const VulkanContext& ctx, const Case& c,
                                const CompiledPipeline& compiled, VkPipelineLayout layout,
                                Cleanup& cleanup, Results& r) {
  StepTimer pipeline_time(r.cost, CostStep::PipelineCreation);
  RAYSPEC_TRY(const RayTracingPipeline pipeline,
              createRayTracingPipeline(ctx, compiled, c.pipeline, layout, cleanup));
  if (ctx.library_group_handles) {
    RAYSPEC_TRY(const std::vector<std::string> mismatches,
                libraryHandleMismatches(ctx, pipeline, &r.library_handles_compared));
    for (const std::string& m : mismatches) r.device_findings.push_back({"R-LIBRARY", m});
  }
  Launch launch;
  launch.bound = {pipeline.pipeline, layout, VK_NULL_HANDLE, std::nullopt};
  if (c.pipeline.callable_depth)
    launch.bound.stack_size =
        pipelineStackSize(queryShaderStackSizes(ctx, compiled, c.pipeline, pipeline),
                          c.pipeline.max_recursion, *c.pipeline.callable_depth);
  pipeline_time.stop();
  StepTimer sbt_time(r.cost, CostStep::Sbt);
  RAYSPEC_TRY(launch.sbt, createSbtBuffer(ctx, c.pipeline, pipeline, cleanup));
  return launch;
}

// Raygen's compute pipeline (Pipeline::from_compute).
Result<Launch> computeLaunch(const VulkanContext& ctx, const CompiledPipeline& compiled,
                             VkPipelineLayout layout, Cleanup& cleanup, Results& r) {
  StepTimer pipeline_time(r.cost, CostStep::PipelineCreation);
  Launch launch;
  RAYSPEC_TRY(launch.bound.pipeline, createComputePipeline(ctx, compiled.raygen, layout, cleanup));
  launch.bound.layout = layout;
  return launch;
}

// Clears the images, launches (trace or dispatch), copies the outputs back
// and waits for the device.
Result<void> recordAndSubmit(const VulkanContext& ctx, const Case& c, const Launch& launch,
                             const CaseBuffers& buffers, Cleanup& cleanup, Results& r) {
  StepTimer trace_time(r.cost, CostStep::Trace);
  RAYSPEC_TRY(const VkCommandBuffer cmd, beginCommands(ctx, cleanup));
  recordImageClears(cmd, buffers.images);
  if (c.pipeline.from_compute) {
    recordDispatch(cmd, launch.bound, c.rays);
  } else {
    RAYSPEC_TRY_VOID(
        recordTrace(ctx, cmd, launch.bound, launch.sbt.layout, launch.sbt.base, c.rays, cleanup));
  }
  recordReadback(cmd, buffers.images, buffers.image_readback, buffers.image_extent.width,
                 buffers.image_extent.height);
  return submitAndWait(ctx, cmd);
}

// The pipeline layout: set 0 of the case's items, or with pipeline.layout:
// empty no set at all, the items' addresses in a table every shader of
// `compiled` is given (vulkan/address_table.h).
struct CaseLayout {
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;  // none: pipeline.layout: empty
  VkPipelineLayout pipeline_layout = VK_NULL_HANDLE;
};
Result<CaseLayout> caseLayout(const VulkanContext& ctx, const Case& c,
                              const std::vector<DescriptorItem>& items, CompiledPipeline& compiled,
                              Cleanup& cleanup) {
  CaseLayout l;
  if (c.pipeline.empty_layout) {
    RAYSPEC_TRY(const VkDeviceAddress table, createAddressTable(ctx, items, cleanup));
    specializeTableAddress(compiled, table);
  } else {
    RAYSPEC_TRY(l.set_layout, createSetLayout(ctx, items, cleanup));
  }
  RAYSPEC_TRY(l.pipeline_layout, createPipelineLayout(ctx, l.set_layout, cleanup));
  return l;
}

}  // namespace

Result<void> runCase(const VulkanContext& ctx, const Case& c, const Plan& plan, Results& r) {
  RAYSPEC_TRY_VOID(checkCaseRuns(ctx, c, plan));
  if (!c.expected_rejections.empty()) {  // compiled, never launched
    compileExpectedRejections(c, plan, r);
    return {};
  }
  StepTimer glsl(r.cost, CostStep::GlslGeneration);
  const GeneratedPipeline generated = generateGlsl(c, plan);
  glsl.stop();
  RAYSPEC_TRY(CompiledPipeline compiled, compilePipeline(generated, &r.cost));

  CaseScope scope(ctx.device, r.cost);
  Cleanup& cleanup = scope.cleanup;
  StepTimer buffer_time(r.cost, CostStep::Buffers);
  RAYSPEC_TRY(const std::set<uint32_t> bindings, caseBindings(plan, declaredBindings(compiled)));
  RAYSPEC_TRY(CaseBuffers buffers, createCaseBuffers(ctx, c, plan, bindings, cleanup));
  buffer_time.stop();

  // The scene's builds in a submission of their own, so that their cost is
  // told apart from the trace's (the build's closing barrier orders them
  // before the trace, across submissions on the one queue).
  StepTimer build_time(r.cost, CostStep::AccelerationBuild);
  std::vector<std::string> overruns;
  std::vector<DeviceFinding> query_findings;
  RAYSPEC_TRY(const std::vector<BuiltStructure> built,
              buildScene(ctx, c.scene, plan.position_fetch ? kBuildAllowDataAccess : 0u, cleanup,
                         overruns, query_findings));
  std::vector<VkAccelerationStructureKHR> tlases;
  for (const BuiltStructure& t : built) tlases.push_back(t.handle);
  for (const std::string& m : overruns) r.device_findings.push_back({"R-AS-MEMORY", m});
  r.device_findings.insert(r.device_findings.end(), query_findings.begin(), query_findings.end());
  build_time.stop();

  StepTimer layout_time(r.cost, CostStep::Buffers);
  std::vector<DescriptorItem> items = descriptorItems(buffers, tlases);
  RAYSPEC_TRY(const CaseLayout layout, caseLayout(ctx, c, items, compiled, cleanup));
  layout_time.stop();
  RAYSPEC_TRY(Launch launch,
              c.pipeline.from_compute
                  ? computeLaunch(ctx, compiled, layout.pipeline_layout, cleanup, r)
                  : rayTracingLaunch(ctx, c, compiled, layout.pipeline_layout, cleanup, r));
  if (layout.set_layout) {
    StepTimer set_time(r.cost, CostStep::Buffers);
    RAYSPEC_TRY(launch.bound.set, createDescriptorSet(ctx, layout.set_layout, items, cleanup));
  }

  RAYSPEC_TRY_VOID(recordAndSubmit(ctx, c, launch, buffers, cleanup, r));
  StepTimer read_time(r.cost, CostStep::ReadBack);
  readResults(buffers, plan, c.rays.width, c.rays.height, r);
  return {};
}

}  // namespace rayspec
