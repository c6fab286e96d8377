// Device errors: what a failed Vulkan call means for the case, the run going
// on after each (a lost device is made again), and limits a case exceeds.
#include <gtest/gtest.h>

#include <tuple>
#include <vector>

#include "plan/plan.h"
#include "result_support.h"
#include "suite_cases.h"
#include "vulkan/context.h"
#include "vulkan/device_errors.h"
#include "vulkan/run_case.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {
namespace {

TEST(DeviceErrors, EachFailedCallHasItsStatus) {
  const DeviceErrorStatus lost =
      classifyVulkanError(deviceError("x", "vkQueueSubmit", VK_ERROR_DEVICE_LOST));
  EXPECT_EQ(lost.status, SideStatus::Crash);
  EXPECT_TRUE(lost.device_lost);
  EXPECT_EQ(
      lost.detail,
      "device lost: vkQueueSubmit returned VK_ERROR_DEVICE_LOST; the next case gets a new device");
  for (VkResult oom : {VK_ERROR_OUT_OF_DEVICE_MEMORY, VK_ERROR_OUT_OF_HOST_MEMORY}) {
    const DeviceErrorStatus s = classifyVulkanError(deviceError("x", "vkAllocateMemory", oom));
    EXPECT_EQ(s.status, SideStatus::NotSupported);
    EXPECT_FALSE(s.device_lost);
    EXPECT_EQ(s.detail.rfind("out of memory: vkAllocateMemory returned VK_ERROR_OUT_OF_", 0), 0u)
        << s.detail;
  }
  const DeviceErrorStatus refused = classifyVulkanError(
      deviceError("x", "vkCreateRayTracingPipelinesKHR", VK_ERROR_INITIALIZATION_FAILED));
  EXPECT_EQ(refused.status, SideStatus::Refused);
  EXPECT_NE(refused.detail.find("the driver refused the pipeline"), std::string::npos);
  const DeviceErrorStatus other = classifyVulkanError(deviceError(
      "vkMapMemory: VK_ERROR_MEMORY_MAP_FAILED", "vkMapMemory", VK_ERROR_MEMORY_MAP_FAILED));
  EXPECT_EQ(other.status, SideStatus::Crash);
  EXPECT_EQ(other.detail, "vkMapMemory: VK_ERROR_MEMORY_MAP_FAILED");
  for (const std::string& name : deviceErrorFaultNames())
    EXPECT_TRUE(deviceErrorFault(name)) << name;
  EXPECT_FALSE(deviceErrorFault("crash"));
}

TEST(DeviceErrors, AFailedCallIsADeviceErrorNamingTheCallAndItsResult) {
  EXPECT_TRUE(vkCheck(VK_SUCCESS, "vkQueueSubmit").ok());
  const Result<void> lost = vkCheck(VK_ERROR_DEVICE_LOST, "vkQueueSubmit");
  ASSERT_FALSE(lost);
  EXPECT_EQ(lost.error().kind, ErrorKind::Device);
  EXPECT_EQ(lost.error().call, "vkQueueSubmit");
  EXPECT_EQ(lost.error().result, "VK_ERROR_DEVICE_LOST");
  EXPECT_EQ(lost.error().message, "vkQueueSubmit: VK_ERROR_DEVICE_LOST");
  EXPECT_TRUE(classifyVulkanError(lost.error()).device_lost);
  // Not one call's failure: a Crash that says what went wrong.
  const DeviceErrorStatus no_call =
      classifyVulkanError(deviceError("no compute queue family: VK_ERROR_FEATURE_NOT_PRESENT"));
  EXPECT_EQ(no_call.status, SideStatus::Crash);
  EXPECT_EQ(no_call.detail, "no compute queue family: VK_ERROR_FEATURE_NOT_PRESENT");
}

Case suiteCase(const std::string& name) {
  const std::optional<CaseFile> f = findCase(name, "", kSuiteCases);
  if (!f) return {};
  ParseResult p = loadSuiteCase(*f);
  return p.value ? *p.value : Case{};
}

// On one device, as --no-isolation runs: a case whose call fails gets its
// status, with no validation message, and the next case passes on the same
// backend (a new VkDevice after a lost one).
TEST(DeviceErrors, TheNextCaseRunsAfterEachError) {
  std::string error;
  auto backend = orError(VulkanEngine::create(VulkanOptions{}), &error);
  if (!backend) GTEST_SKIP() << "no Vulkan ray tracing device: " << error;
  const Case c = suiteCase("sbt/hit-group-index");
  ASSERT_FALSE(c.name.empty());
  const Plan plan = derivePlan(c);
  const Results clean = backend->run(c, plan);
  ASSERT_TRUE(clean.ok()) << clean.statusText();
  const std::pair<const char*, SideStatus> faults[] = {
      {"device-lost", SideStatus::Crash},
      {"out-of-device-memory", SideStatus::NotSupported},
      {"pipeline-refused", SideStatus::Refused}};
  for (const auto& [name, status] : faults) {
    injectVkError(*deviceErrorFault(name));
    const Results failed = backend->run(c, plan);
    injectVkError({});
    EXPECT_EQ(failed.status, status) << name << ": " << failed.statusText();
    EXPECT_TRUE(failed.records.empty()) << name;
    EXPECT_TRUE(failed.validation_messages.empty())
        << name << ": " << failed.validation_messages.front();
    const Results next = backend->run(c, plan);
    EXPECT_TRUE(next.ok()) << "after " << name << ": " << next.statusText();
    EXPECT_EQ(next.records, clean.records) << "after " << name;
    EXPECT_TRUE(next.validation_messages.empty())
        << name << ": " << next.validation_messages.front();
  }
  EXPECT_TRUE(backend->close().empty()) << "every object of the failed cases was destroyed";
}

// A launch beyond the device's limits is NotSupported before anything is built.
// A device whose limits fit every case checked here (no Vulkan behind it).
VulkanContext ampleContext() {
  VulkanContext ctx;
  ctx.info.max_ray_recursion_depth = 31;
  for (uint64_t& size : ctx.info.max_launch_size) size = 1u << 16;
  ctx.info.max_ray_dispatch_invocation_count = 1u << 20;
  ctx.info.shader_group_handle_size = 32;
  ctx.info.shader_group_handle_alignment = 32;
  ctx.info.shader_group_base_alignment = 64;
  ctx.info.max_shader_group_stride = 4096;
  ctx.info.ray_traversal_primitive_culling = true;
  return ctx;
}

TEST(DeviceErrors, ADispatchTooLargeForTheDeviceIsNotSupported) {
  const Case c = suiteCase("sbt/hit-group-index");  // a 6x3 launch
  ASSERT_FALSE(c.name.empty());
  VulkanContext ctx = ampleContext();
  EXPECT_TRUE(checkCaseSupport(ctx, c, derivePlan(c)).ok());
  ctx.info.max_ray_dispatch_invocation_count = 17;
  const Result<void> too_many = checkCaseSupport(ctx, c, derivePlan(c));
  ASSERT_FALSE(too_many);
  EXPECT_EQ(too_many.error().kind, ErrorKind::NotSupported);
  EXPECT_EQ(too_many.error().message, "launch of 18 rays > maxRayDispatchInvocationCount 17");
  ctx.info.max_ray_dispatch_invocation_count = 1u << 20;
  ctx.info.max_launch_size[0] = 5;
  const Result<void> too_wide = checkCaseSupport(ctx, c, derivePlan(c));
  ASSERT_FALSE(too_wide);
  EXPECT_EQ(too_wide.error().kind, ErrorKind::NotSupported);
}

TEST(DeviceErrors, AnIndirectTraceWithoutItsFeatureIsNotSupported) {
  for (const char* name : {"sbt/indirect/indirect-4x3", "sbt/indirect/indirect2-4x3"}) {
    SCOPED_TRACE(name);
    const Case c = suiteCase(name);
    ASSERT_FALSE(c.name.empty());
    VulkanContext ctx = ampleContext();
    ctx.info.trace_rays_indirect = ctx.info.trace_rays_indirect2 = true;
    EXPECT_TRUE(checkCaseSupport(ctx, c, derivePlan(c)).ok());
    ctx.info.trace_rays_indirect = ctx.info.trace_rays_indirect2 = false;
    const Result<void> lacking = checkCaseSupport(ctx, c, derivePlan(c));
    ASSERT_FALSE(lacking);
    EXPECT_EQ(lacking.error().kind, ErrorKind::NotSupported);
    EXPECT_NE(lacking.error().message.find("rays.command indirect"), std::string::npos)
        << lacking.error().message;
  }
}

TEST(DeviceErrors, TheCullMaskBuiltinWithoutMaintenance1IsNotSupported) {
  const Case c = suiteCase("builtins/cull-mask");
  ASSERT_FALSE(c.name.empty());
  const Plan plan = derivePlan(c);
  ASSERT_TRUE(plan.cull_mask_builtin);
  VulkanContext ctx = ampleContext();
  ctx.info.ray_tracing_maintenance1 = true;
  EXPECT_TRUE(checkCaseSupport(ctx, c, plan).ok());
  ctx.info.ray_tracing_maintenance1 = false;
  const Result<void> lacking = checkCaseSupport(ctx, c, plan);
  ASSERT_FALSE(lacking);
  EXPECT_EQ(lacking.error().kind, ErrorKind::NotSupported);
  EXPECT_NE(lacking.error().message.find("VK_KHR_ray_tracing_maintenance1"), std::string::npos)
      << lacking.error().message;
}

// The link-time pipeline flags need VK_EXT_graphics_pipeline_library
// (enabled where offered); without it the case is NotSupported, named.
TEST(DeviceErrors, LinkTimeFlagsWithoutGraphicsPipelineLibraryAreNotSupported) {
  for (const char* name : {"anyhit/through-libraries/nested-link-time-optimization",
                           "anyhit/through-libraries/nested-retain-link-time-info"}) {
    SCOPED_TRACE(name);
    const Case c = suiteCase(name);
    ASSERT_FALSE(c.name.empty());
    VulkanContext ctx = ampleContext();
    ctx.info.pipeline_library = ctx.info.graphics_pipeline_library = true;
    EXPECT_TRUE(checkCaseSupport(ctx, c, derivePlan(c)).ok());
    ctx.info.graphics_pipeline_library = false;
    const Result<void> lacking = checkCaseSupport(ctx, c, derivePlan(c));
    ASSERT_FALSE(lacking);
    EXPECT_EQ(lacking.error().kind, ErrorKind::NotSupported);
    EXPECT_NE(lacking.error().message.find("VK_EXT_graphics_pipeline_library"), std::string::npos)
        << lacking.error().message;
  }
}

// A sized scalar needs its device feature: each missing one is
// NotSupported, the feature named (program/sized_types.h's column).
TEST(DeviceErrors, ASizedScalarWithoutItsFeatureIsNotSupported) {
  const std::vector<std::tuple<const char*, bool DeviceInfo::*, const char*>> rows = {
      {"control/live-state-sized/int8", &DeviceInfo::shader_int8, "shaderInt8"},
      {"control/live-state-sized/uint16", &DeviceInfo::shader_int16, "shaderInt16"},
      {"control/live-state-sized/float16", &DeviceInfo::shader_float16, "shaderFloat16"},
      {"control/live-state-sized/uint64", &DeviceInfo::shader_int64, "shaderInt64"},
      {"control/live-state-sized/float64", &DeviceInfo::shader_float64, "shaderFloat64"},
      {"control/live-state-sized-vectors/uint8", &DeviceInfo::shader_int8, "shaderInt8"},
      {"control/live-state-sized-vectors/float16", &DeviceInfo::shader_float16, "shaderFloat16"},
      {"control/live-state-sized-vectors/int64", &DeviceInfo::shader_int64, "shaderInt64"},
      {"interface/sized-data/int16", &DeviceInfo::shader_int16, "shaderInt16"},
      {"interface/sized-hit-attributes/f64vec3", &DeviceInfo::shader_float64, "shaderFloat64"}};
  for (const auto& [name, feature, feature_name] : rows) {
    SCOPED_TRACE(name);
    const Case c = suiteCase(name);
    ASSERT_FALSE(c.name.empty());
    VulkanContext ctx = ampleContext();
    ctx.info.*feature = true;
    EXPECT_TRUE(checkCaseSupport(ctx, c, derivePlan(c)).ok());
    ctx.info.*feature = false;
    const Result<void> lacking = checkCaseSupport(ctx, c, derivePlan(c));
    ASSERT_FALSE(lacking);
    EXPECT_EQ(lacking.error().kind, ErrorKind::NotSupported);
    EXPECT_NE(lacking.error().message.find(feature_name), std::string::npos)
        << lacking.error().message;
  }
}

// A sized member a payload, callable data or hit attribute type declares
// needs its feature though no program reads it: every stage declares the
// type (the plan notes it as a sized local's).
TEST(DeviceErrors, ADeclaredSizedMemberWithoutItsFeatureIsNotSupported) {
  VulkanContext ctx = ampleContext();
  ctx.info.shader_float16 = false;
  for (int where = 0; where < 3; ++where) {
    SCOPED_TRACE(where);
    Case c = suiteCase("interface/indexed-words");
    ASSERT_FALSE(c.name.empty());
    ASSERT_TRUE(checkCaseSupport(ctx, c, derivePlan(c)).ok());
    const SizedMembers f16{ValueType::Float16Vec3};
    if (where == 0) c.pipeline.payload_sized.back() = f16;
    if (where == 1) c.pipeline.call_data_sized.back() = f16;
    if (where == 2) c.pipeline.attribute_sized = f16;
    const Result<void> lacking = checkCaseSupport(ctx, c, derivePlan(c));
    ASSERT_FALSE(lacking);
    EXPECT_EQ(lacking.error().kind, ErrorKind::NotSupported);
    EXPECT_NE(lacking.error().message.find("shaderFloat16"), std::string::npos)
        << lacking.error().message;
  }
}

// int32 (ivec2 .. ivec4) is core: a device without any of the sized
// features still runs it (its row's feature is empty).
TEST(DeviceErrors, Int32VectorsNeedNoFeature) {
  const Case c = suiteCase("control/live-state-sized-vectors/int32");
  ASSERT_FALSE(c.name.empty());
  VulkanContext ctx = ampleContext();
  ctx.info.shader_int8 = ctx.info.shader_int16 = ctx.info.shader_int64 = false;
  ctx.info.shader_float16 = ctx.info.shader_float64 = false;
  EXPECT_TRUE(checkCaseSupport(ctx, c, derivePlan(c)).ok());
}

// tlas: expr indexes the array of top levels with nonuniformEXT: a device
// without descriptorIndexing (VK_EXT_descriptor_indexing) is NotSupported,
// the feature named.
TEST(DeviceErrors, ADynamicTopLevelIndexWithoutDescriptorIndexingIsNotSupported) {
  for (const char* name : {"ray-query/dynamic-tlas-index", "descriptors/tlas-array/indexed",
                           "descriptors/tlas-array/through-function"}) {
    SCOPED_TRACE(name);
    const Case c = suiteCase(name);
    ASSERT_FALSE(c.name.empty());
    const Plan plan = derivePlan(c);
    ASSERT_TRUE(plan.dynamic_tlas_index);
    VulkanContext ctx = ampleContext();
    ctx.info.ray_query = ctx.info.descriptor_indexing = true;
    EXPECT_TRUE(checkCaseSupport(ctx, c, plan).ok());
    ctx.info.descriptor_indexing = false;
    const Result<void> lacking = checkCaseSupport(ctx, c, plan);
    ASSERT_FALSE(lacking);
    EXPECT_EQ(lacking.error().kind, ErrorKind::NotSupported);
    EXPECT_NE(lacking.error().message.find("descriptorIndexing"), std::string::npos)
        << lacking.error().message;
  }
  EXPECT_FALSE(derivePlan(suiteCase("inactive/top-levels")).dynamic_tlas_index);  // constants
}

}  // namespace
}  // namespace rayspec
