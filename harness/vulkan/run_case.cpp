#include "vulkan/run_case.h"

#include <algorithm>

#include "case/flag_names.h"
#include "glsl/generate_glsl.h"
#include "vulkan/acceleration_structure.h"
#include "vulkan/case_buffers.h"
#include "vulkan/commands.h"
#include "vulkan/descriptors.h"
#include "vulkan/pipeline.h"
#include "vulkan/sbt_buffer.h"
#include "vulkan/stack_size.h"
#include "vulkan/trace.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

constexpr uint64_t kTraceTimeoutNs = 240ull * 1000 * 1000 * 1000;

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

bool usesSkipRayFlags(const Rays& rays) {
  const uint32_t skip = kRaySkipTriangles | kRaySkipAabbs;
  if (rays.defaults.flags & skip) return true;
  for (const Ray& r : rays.rays)
    if (r.flags & skip) return true;
  return false;
}

std::string sizeText(const uint64_t (&size)[3]) {
  return std::to_string(size[0]) + " x " + std::to_string(size[1]) + " x " +
         std::to_string(size[2]);
}

// Each dimension within maxComputeWorkGroupCount * maxComputeWorkGroupSize.
void checkLaunchSize(const DeviceInfo& d, const std::array<uint32_t, 3>& launch) {
  const uint64_t size[3] = {launch[0], launch[1], launch[2]};
  for (int k = 0; k < 3; ++k)
    if (size[k] > d.max_launch_size[k])
      throw NotSupportedError("launch " + sizeText(size) +
                              " > maxComputeWorkGroupCount * maxComputeWorkGroupSize (" +
                              sizeText(d.max_launch_size) + ")");
}

// R-VERTEX-FORMAT: every vertex format the scene uses must be one the device
// builds acceleration structures from.
void checkVertexFormats(const VulkanContext& ctx, const Scene& scene) {
  for (const Blas& b : scene.blases)
    for (const Geometry& g : b.geometries) {
      if (g.kind != Geometry::Kind::Triangles || g.vertex_format == VertexFormat::Float3) continue;
      VkFormatProperties props{};
      vkGetPhysicalDeviceFormatProperties(ctx.physical, vkVertexFormat(g.vertex_format), &props);
      if (!(props.bufferFeatures & VK_FORMAT_FEATURE_ACCELERATION_STRUCTURE_VERTEX_BUFFER_BIT_KHR))
        throw NotSupportedError("triangles.vertex_format " +
                                std::string(vertexFormatName(g.vertex_format)) +
                                ": the device cannot build acceleration structures from it");
    }
}

}  // namespace

void checkCaseSupport(const VulkanContext& ctx, const Case& c, const Plan& plan) {
  const DeviceInfo& d = ctx.info;
  const std::array<uint32_t, 3> launch = c.rays.launchSize();
  const uint64_t launch_rays = uint64_t(launch[0]) * launch[1] * launch[2];
  if (c.rays.rays.size() != static_cast<size_t>(c.rays.width) * c.rays.height ||
      c.rays.rays.size() != launch_rays)
    throw VulkanError("case has " + std::to_string(c.rays.rays.size()) + " rays for a " +
                      std::to_string(c.rays.width) + "x" + std::to_string(c.rays.height) +
                      " launch: VK_ERROR_UNKNOWN");
  const bool micromap_flags =
      std::any_of(c.scene.instances.begin(), c.scene.instances.end(),
                  [](const Instance& i) { return i.flags & kInstanceOpacityMicromapFlags; });
  if (micromap_flags && !(d.opacity_micromap && d.api_version_number >= VK_API_VERSION_1_3))
    throw NotSupportedError(
        "scene.instances[].flags: opacity micromap flags need VK_EXT_opacity_micromap");
  if (c.rays.command == TraceCommand::Indirect && !d.trace_rays_indirect)
    throw NotSupportedError(
        "rays.command indirect: the device lacks rayTracingPipelineTraceRaysIndirect");
  if (c.rays.command == TraceCommand::Indirect2 && !d.trace_rays_indirect2)
    throw NotSupportedError(
        "rays.command indirect2: the device lacks VK_KHR_ray_tracing_maintenance1's "
        "rayTracingPipelineTraceRaysIndirect2");
  if (plan.cull_mask_builtin && !d.ray_tracing_maintenance1)
    throw NotSupportedError(
        "cull_mask: gl_CullMaskEXT needs VK_KHR_ray_tracing_maintenance1 (rayTracingMaintenance1)");
  if (!c.pipeline.libraries.empty() && !d.pipeline_library)
    throw NotSupportedError("pipeline.libraries: the device lacks VK_KHR_pipeline_library");
  if (c.pipeline.max_recursion > d.max_ray_recursion_depth)
    throw NotSupportedError("max_recursion " + std::to_string(c.pipeline.max_recursion) +
                            " > device maxRayRecursionDepth " +
                            std::to_string(d.max_ray_recursion_depth));
  checkLaunchSize(d, launch);
  checkVertexFormats(ctx, c.scene);
  if (launch_rays > d.max_ray_dispatch_invocation_count)
    throw NotSupportedError("launch of " + std::to_string(launch_rays) +
                            " rays > maxRayDispatchInvocationCount " +
                            std::to_string(d.max_ray_dispatch_invocation_count));
  if (!ctx.primitive_culling &&
      ((c.pipeline.flags & (kPipelineSkipTriangles | kPipelineSkipAabbs)) ||
       usesSkipRayFlags(c.rays)))
    throw NotSupportedError("skip_triangles / skip_aabbs need rayTraversalPrimitiveCulling");
  // The shader binding table's shape (pipeline.sbt.record_data / padding):
  // a stride above maxShaderGroupStride, or any layout the device's limits
  // refuse, before anything is built.
  const SbtLimits limits = deviceSbtLimits(ctx);
  const Pipeline& p = c.pipeline;
  if (const Result<void> fits = checkSbtLayout(computeSbtLayout(limits, p), limits); !fits)
    throw NotSupportedError(
        fits.error().format() + " (a record is the " + std::to_string(limits.handle_size) +
        "-byte handle + pipeline.sbt.record_data " + std::to_string(p.sbt_record_data) +
        " + pipeline.sbt.padding: miss " + std::to_string(p.sbt_padding.miss) + ", hit " +
        std::to_string(p.sbt_padding.hit) + ", callable " + std::to_string(p.sbt_padding.callable) +
        " bytes, aligned up to shaderGroupHandleAlignment " +
        std::to_string(limits.handle_alignment) + ")");
}

void runCase(const VulkanContext& ctx, const Case& c, const Plan& plan, Results& r) {
  checkCaseSupport(ctx, c, plan);
  StepTimer glsl(r.cost, CostStep::GlslGeneration);
  const GeneratedPipeline generated = generateGlsl(c, plan);
  glsl.stop();
  CompiledPipeline compiled = compilePipeline(generated, &r.cost);

  CaseScope scope(ctx.device, r.cost);
  Cleanup& cleanup = scope.cleanup;
  StepTimer buffer_time(r.cost, CostStep::Buffers);
  CaseBuffers buffers =
      createCaseBuffers(ctx, c, plan, caseBindings(plan, declaredBindings(compiled)), cleanup);
  buffer_time.stop();

  // The scene's builds in a submission of their own, so that their cost is
  // told apart from the trace's (the build's closing barrier orders them
  // before the trace, across submissions on the one queue).
  StepTimer build_time(r.cost, CostStep::AccelerationBuild);
  const std::vector<VkAccelerationStructureKHR> tlases = buildScene(ctx, c.scene, cleanup);
  build_time.stop();

  StepTimer layout_time(r.cost, CostStep::Buffers);
  std::vector<DescriptorItem> items = descriptorItems(buffers, tlases);
  VkDescriptorSetLayout set_layout = createSetLayout(ctx, items, cleanup);
  VkPipelineLayout pipeline_layout = createPipelineLayout(ctx, set_layout, cleanup);
  layout_time.stop();
  StepTimer pipeline_time(r.cost, CostStep::PipelineCreation);
  const RayTracingPipeline pipeline =
      createRayTracingPipeline(ctx, compiled, c.pipeline, pipeline_layout, cleanup);
  std::optional<VkDeviceSize> stack_size;
  if (c.pipeline.callable_depth)
    stack_size = pipelineStackSize(queryShaderStackSizes(ctx, compiled, c.pipeline, pipeline),
                                   c.pipeline.max_recursion, *c.pipeline.callable_depth);
  pipeline_time.stop();
  StepTimer sbt_time(r.cost, CostStep::Sbt);
  SbtBuffer sbt = createSbtBuffer(ctx, c.pipeline, pipeline, cleanup);
  sbt_time.stop();
  StepTimer set_time(r.cost, CostStep::Buffers);
  VkDescriptorSet set = createDescriptorSet(ctx, set_layout, items, cleanup);
  set_time.stop();

  StepTimer trace_time(r.cost, CostStep::Trace);
  VkCommandBuffer cmd = beginCommands(ctx, cleanup);
  recordImageClears(cmd, buffers.images);
  recordTrace(ctx, cmd, {pipeline.pipeline, pipeline_layout, set, stack_size}, sbt.layout, sbt.base,
              c.rays, cleanup);
  recordReadback(cmd, buffers.images, buffers.image_readback, buffers.image_extent.width,
                 buffers.image_extent.height);
  submitAndWait(ctx, cmd, kTraceTimeoutNs);
  trace_time.stop();
  StepTimer read_time(r.cost, CostStep::ReadBack);
  readResults(buffers, plan, c.rays.width, c.rays.height, r);
}

}  // namespace rayspec
