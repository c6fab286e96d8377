// Whether the device can run a case: the features, extensions and limits the
// case needs, each missing one a NotSupported error that names it.
#include "vulkan/case_support.h"

#include <algorithm>

#include "case/flag_names.h"
#include "vulkan/acceleration_structure.h"
#include "vulkan/position_fetch.h"
#include "vulkan/run_case.h"
#include "vulkan/sbt_buffer.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

// The first validation layer version not known to crash deferred pipelines.
constexpr uint32_t kDeferredLayerVersion = VK_MAKE_API_VERSION(0, 1, 3, 240);

bool usesSkipRayFlags(const Rays& rays) {
  const uint32_t skip = kRaySkipTriangles | kRaySkipAabbs;
  if (rays.defaults.flags & skip) return true;
  for (const Ray& r : rays.rays)
    if (r.flags & skip) return true;
  return false;
}

std::string sizeText(const DeviceLaunchSize& size) {
  return std::to_string(size[0]) + " x " + std::to_string(size[1]) + " x " +
         std::to_string(size[2]);
}

// Each dimension within maxComputeWorkGroupCount * maxComputeWorkGroupSize.
Result<void> checkLaunchSize(const DeviceInfo& d, const std::array<uint32_t, 3>& launch) {
  const DeviceLaunchSize size = {launch[0], launch[1], launch[2]};
  for (int k = 0; k < 3; ++k)
    if (size[k] > d.max_launch_size[k])
      return notSupported("launch " + sizeText(size) +
                          " > maxComputeWorkGroupCount * maxComputeWorkGroupSize (" +
                          sizeText(d.max_launch_size) + ")");
  return {};
}

// R-VERTEX-FORMAT: every vertex format the scene uses must be one the device
// builds acceleration structures from (DeviceInfo::vertex_formats).
Result<void> checkVertexFormats(const DeviceInfo& d, const Scene& scene) {
  for (const Blas& b : scene.blases)
    for (const Geometry& g : b.geometries) {
      if (g.kind != Geometry::Kind::Triangles || g.vertex_format == VertexFormat::Float3) continue;
      const std::string name = vertexFormatName(g.vertex_format);
      if (std::find(d.vertex_formats.begin(), d.vertex_formats.end(), name) ==
          d.vertex_formats.end())
        return notSupported("triangles.vertex_format " + name +
                            ": the device cannot build acceleration structures from it");
    }
  return {};
}

// gl_HitTriangleVertexPositionsEXT: the device's feature, and a validation
// layer (when on) that knows the extension.
Result<void> checkPositionFetch(const DeviceInfo& d, uint32_t validation_layer) {
  if (!d.position_fetch)
    return notSupported(
        "vertex_position<i>: gl_HitTriangleVertexPositionsEXT needs "
        "VK_KHR_ray_tracing_position_fetch (rayTracingPositionFetch)");
  if (!validationLayerKnows(validation_layer, kPositionFetchHeaderVersion))
    return notSupported(
        "vertex_position<i>: the validation layer (" + vulkanVersionText(validation_layer) +
        ") predates VK_KHR_ray_tracing_position_fetch (1.3.249) and would report its SPIR-V as "
        "an error; a newer layer runs it (tools/second-driver.sh)");
  return {};
}

// How scene.build records its builds and binds its memory.
Result<void> checkBuildSupport(const DeviceInfo& d, const AsBuild& build) {
  if (build.command == BuildCommand::Indirect && !d.acceleration_structure_indirect_build)
    return notSupported(
        "scene.build.command indirect: the device lacks accelerationStructureIndirectBuild");
  if (build.sparse.any() && !d.sparse_binding)
    return notSupported("scene.build.sparse: the device lacks sparseBinding");
  if (build.sparse.any() && !d.sparse_binding_queue)
    return notSupported(
        "scene.build.sparse: the queue family rayspec runs on (the first with compute) lacks "
        "VK_QUEUE_SPARSE_BINDING_BIT");
  if (build.queries.command == QueryCommand::Host && !d.acceleration_structure_host_commands)
    return notSupported(
        "scene.build.query_command host: vkWriteAccelerationStructuresPropertiesKHR needs "
        "accelerationStructureHostCommands, which the device lacks");
  if (build.queries.needsMaintenance1() && !d.ray_tracing_maintenance1)
    return notSupported(
        "scene.build.queries size, bottom_level_pointers: the device lacks "
        "VK_KHR_ray_tracing_maintenance1 (rayTracingMaintenance1)");
  if (build.command == BuildCommand::Host)
    return notSupported(
        d.acceleration_structure_host_commands
            ? "scene.build.command host: rayspec records no host builds yet (the device has "
              "accelerationStructureHostCommands)"
            : "scene.build.command host: the device lacks accelerationStructureHostCommands");
  return {};
}

// pipeline.deferred: the extension, and no validation layer known to break
// it: under Debian 12's layer (1.3.239) a pipeline created through a
// deferred operation crashes lavapipe 25.0.7 when its group handles are read
// (every anyhit/deferred-creation row; all pass without the layer).
// lavapipe completes the creation at once (VK_SUCCESS), and layers of that
// age wrap such a pipeline's handle only on a completion path a driver that
// does not defer never takes (Vulkan-ValidationLayers issue 5817; the
// completion work moved into vkGetDeferredOperationResultKHR in 2024, pull
// request 8364): the crash matches that bug, not a reproduced diagnosis.
// Newer layers are not excluded: untried.
Result<void> checkDeferred(const DeviceInfo& d, uint32_t validation_layer) {
  if (!d.acceleration_structure_extension)
    return notSupported("pipeline.deferred: the device lacks VK_KHR_deferred_host_operations");
  if (!validationLayerKnows(validation_layer, kDeferredLayerVersion))
    return notSupported("pipeline.deferred: under the validation layer (" +
                        vulkanVersionText(validation_layer) +
                        ") a pipeline made through a deferred operation the driver completes at "
                        "once crashes when used (likely the layer's unwrapped-handle bug, "
                        "Vulkan-ValidationLayers issue 5817); runs without it (--no-validation) "
                        "or under a newer layer");
  return {};
}

// The device feature each sized scalar the case computes with needs
// (program/sized_types.h's feature column names it; int32 needs none).
Result<void> checkSizedTypes(const DeviceInfo& d, const Plan& plan) {
  for (ValueType t : enumValues<ValueType>()) {
    const bool DeviceInfo::*feature = sizedTypeFeature(t);
    if (!feature || !isSizedScalar(t) || !plan.usesSized(t) || d.*feature) continue;
    return notSupported(std::string(valueTypeSpelling(t)) +
                        " values (locals, payload, callable data or hit attribute members): the "
                        "device lacks " +
                        sizedType(t)->feature);
  }
  return {};
}

// How the pipeline object is made: its record block layout, libraries,
// flags, deferred creation and recursion depth.
Result<void> checkPipelineObjects(const DeviceInfo& d, uint32_t validation_layer, const Pipeline& p,
                                  const Plan& plan) {
  if (p.record_layout.declared() && p.record_layout.scalar && !d.scalar_block_layout)
    return notSupported(
        "pipeline.sbt.record_layout: a scalar shader record block needs scalarBlockLayout");
  if (plan.cull_mask_builtin && !d.ray_tracing_maintenance1)
    return notSupported(
        "cull_mask: gl_CullMaskEXT needs VK_KHR_ray_tracing_maintenance1 (rayTracingMaintenance1)");
  if (!p.libraries.empty() && !d.pipeline_library)
    return notSupported("pipeline.libraries: the device lacks VK_KHR_pipeline_library");
  if ((p.flags & kPipelineLinkTimeFlags) && !d.graphics_pipeline_library)
    return notSupported(
        "pipeline.flags link_time_optimization, retain_link_time_optimization_info: the device "
        "lacks VK_EXT_graphics_pipeline_library");
  if (p.deferred_threads) RAYSPEC_TRY_VOID(checkDeferred(d, validation_layer));
  if (p.max_recursion > d.max_ray_recursion_depth)
    return notSupported("max_recursion " + std::to_string(p.max_recursion) +
                        " > device maxRayRecursionDepth " +
                        std::to_string(d.max_ray_recursion_depth));
  return {};
}

}  // namespace

bool DeviceInfo::*sizedTypeFeature(ValueType t) {
  const SizedType* s = sizedType(t);
  if (!s || !*s->feature) return nullptr;
  if (s->kind == SizedKind::Floating)
    return s->bits == 16 ? &DeviceInfo::shader_float16 : &DeviceInfo::shader_float64;
  return s->bits == 8    ? &DeviceInfo::shader_int8
         : s->bits == 16 ? &DeviceInfo::shader_int16
                         : &DeviceInfo::shader_int64;
}

bool validationLayerKnows(uint32_t validation_layer, uint32_t since) {
  return validation_layer == 0 || validation_layer >= since;
}

Result<void> checkCaseSupport(const DeviceInfo& d, uint32_t validation_layer, const Case& c,
                              const Plan& plan) {
  const std::array<uint32_t, 3> launch = c.rays.launchSize();
  const uint64_t launch_rays = uint64_t(launch[0]) * launch[1] * launch[2];
  if (c.rays.launchRays() != static_cast<size_t>(c.rays.width) * c.rays.height ||
      c.rays.launchRays() != launch_rays)
    return deviceError("case has " + std::to_string(c.rays.launchRays()) + " rays for a " +
                       std::to_string(c.rays.width) + "x" + std::to_string(c.rays.height) +
                       " launch: VK_ERROR_UNKNOWN");
  const bool micromap_flags =
      std::any_of(c.scene.instances.begin(), c.scene.instances.end(),
                  [](const Instance& i) { return i.flags & kInstanceOpacityMicromapFlags; });
  if (micromap_flags && !(d.opacity_micromap && d.api_version_number >= VK_API_VERSION_1_3))
    return notSupported(
        "scene.instances[].flags: opacity micromap flags need VK_EXT_opacity_micromap");
  if (c.rays.command == TraceCommand::Indirect && !d.trace_rays_indirect)
    return notSupported(
        "rays.command indirect: the device lacks rayTracingPipelineTraceRaysIndirect");
  if (c.rays.command == TraceCommand::Indirect2 && !d.trace_rays_indirect2)
    return notSupported(
        "rays.command indirect2: the device lacks VK_KHR_ray_tracing_maintenance1's "
        "rayTracingPipelineTraceRaysIndirect2");
  RAYSPEC_TRY_VOID(checkBuildSupport(d, c.scene.build));
  RAYSPEC_TRY_VOID(checkSizedTypes(d, plan));
  if (plan.position_fetch) RAYSPEC_TRY_VOID(checkPositionFetch(d, validation_layer));
  if ((c.pipeline.ray_query || c.pipeline.ray_query_in_hit) && !d.ray_query)
    return notSupported(
        "traces by ray query (--through ray-query, ray-query-compute, ray-query-in-hit): the "
        "device lacks VK_KHR_ray_query's rayQuery");
  if (plan.dynamic_tlas_index && !d.descriptor_indexing)
    return notSupported(
        "tlas: expr: top levels indexed dynamically (rs_tlas[nonuniformEXT(i)]) need "
        "descriptorIndexing (VK_EXT_descriptor_indexing), which the device lacks");
  if (plan.hit_objects && !d.invocation_reorder)
    return notSupported(
        "hit objects (hit_object.*, hit_object_record_*, trace hit_object, execute, record_hit, "
        "record_miss, record_empty, reorder): the device lacks "
        "VK_NV_ray_tracing_invocation_reorder (rayTracingInvocationReorder)");
  if (plan.ray_queries && !d.ray_query)
    return notSupported("ray_query statements: the device lacks VK_KHR_ray_query's rayQuery");
  RAYSPEC_TRY_VOID(checkPipelineObjects(d, validation_layer, c.pipeline, plan));
  RAYSPEC_TRY_VOID(checkLaunchSize(d, launch));
  RAYSPEC_TRY_VOID(checkVertexFormats(d, c.scene));
  if (launch_rays > d.max_ray_dispatch_invocation_count)
    return notSupported("launch of " + std::to_string(launch_rays) +
                        " rays > maxRayDispatchInvocationCount " +
                        std::to_string(d.max_ray_dispatch_invocation_count));
  if (!d.ray_traversal_primitive_culling &&
      ((c.pipeline.flags & (kPipelineSkipTriangles | kPipelineSkipAabbs)) ||
       usesSkipRayFlags(c.rays)))
    return notSupported("skip_triangles / skip_aabbs need rayTraversalPrimitiveCulling");
  // The shader binding table's shape (pipeline.sbt.record_data / padding):
  // a stride above maxShaderGroupStride, or any layout the device's limits
  // refuse, before anything is built.
  const SbtLimits limits = sbtLimits(d);
  const Pipeline& p = c.pipeline;
  if (const Result<void> fits = checkSbtLayout(computeSbtLayout(limits, p), limits); !fits)
    return notSupported(
        fits.error().format() + " (a record is the " + std::to_string(limits.handle_size) +
        "-byte handle + pipeline.sbt.record_data " + std::to_string(p.sbt_record_data) +
        " + pipeline.sbt.padding: miss " + std::to_string(p.sbt_padding.miss) + ", hit " +
        std::to_string(p.sbt_padding.hit) + ", callable " + std::to_string(p.sbt_padding.callable) +
        " bytes, aligned up to shaderGroupHandleAlignment " +
        std::to_string(limits.handle_alignment) + ")");
  return {};
}

Result<void> checkCaseRuns(const DeviceInfo& d, uint32_t validation_layer, const Case& c,
                           const Plan& plan) {
  if (!c.expected_rejections.empty()) return {};
  return checkCaseSupport(d, validation_layer, c, plan);
}

Result<void> checkCaseSupport(const VulkanContext& ctx, const Case& c, const Plan& plan) {
  return checkCaseSupport(ctx.info, ctx.validation ? ctx.validation_layer_version : 0, c, plan);
}

Result<void> checkCaseRuns(const VulkanContext& ctx, const Case& c, const Plan& plan) {
  return checkCaseRuns(ctx.info, ctx.validation ? ctx.validation_layer_version : 0, c, plan);
}

}  // namespace rayspec
