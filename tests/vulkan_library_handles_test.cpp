// VK_EXT_pipeline_library_group_handles (R-LIBRARY): with the feature on, the
// run compares every library group's handle read from its library with its
// handle in the linked pipeline; lavapipe's are identical. Under a
// validation layer older than the extension the feature stays off.
#include <gtest/gtest.h>

#include "parse_support.h"
#include "plan/plan.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {
namespace {

Case libraryCase() {
  return parsedCase(
      "rules: [R-LIBRARY]\n"
      "scene:\n"
      "  blas:\n"
      "    tri: [{triangles: {vertices: [[-1, -1, 0], [1, -1, 0], [-1, 1, 0]]}}]\n"
      "  instances: [{blas: tri}]\n"
      "rays:\n"
      "  list: [{origin: [-0.5, -0.5, 1], direction: [0, 0, -1]}, {origin: [5, 5, 1], "
      "direction: [0, 0, -1]}]\n"
      "pipeline:\n"
      "  miss: [[record: {hit: 0}]]\n"
      "  hit_groups: [{closest_hit: [record: [hit]]}]\n"
      "  libraries: [{miss: [0], libraries: [{hit_groups: [0]}]}]\n"
      "outputs:\n"
      "  per_ray: [hit]\n");
}

bool deviceHasGroupHandles() {
  const Result<std::vector<DeviceInfo>> devices = listDevices();
  if (!devices) return false;
  for (const DeviceInfo& d : *devices)
    if (d.ray_tracing_pipeline && d.library_group_handles) return true;
  return false;
}

TEST(LibraryGroupHandles, EveryLibraryGroupIsComparedAndIdentical) {
  if (!deviceHasGroupHandles())
    GTEST_SKIP() << "no device with VK_EXT_pipeline_library_group_handles";
  VulkanOptions options;
  options.validation = false;  // any layer: the feature is on without one
  Result<std::unique_ptr<VulkanEngine>> engine = VulkanEngine::create(options);
  ASSERT_TRUE(engine) << engine.error().format();
  const Case c = libraryCase();
  const Results r = (*engine)->run(c, derivePlan(c));
  ASSERT_TRUE(r.ok()) << r.statusText();
  EXPECT_EQ(r.library_handles_compared, 2u);  // the miss group and the hit group
  EXPECT_TRUE(r.device_findings.empty()) << r.device_findings.front().message;
}

}  // namespace
}  // namespace rayspec
