// A top level rebuilt after a compacting copy (scene.build copy compact,
// tlas_update rebuild, an update after the copy): a build (MODE_BUILD)
// needs a destination of the build's accelerationStructureSize
// (VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-10126; a compacted size
// is enough only to update), so the rebuild writes a new structure of that
// size and the traces use it, where an update after the copy updates the
// compacted copy in place. On lavapipe the compacted size is the build size,
// so the sizes alone do not tell the two apart: a rebuild into the compacted
// copy (as before) is refused by Builds::checkRoom, and this build would
// fail. And the guards are checked once each copy ended,
// so a write past a size after the copy is told apart from the copy's own.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "case/flag_names.h"
#include "live_device.h"
#include "parse_support.h"
#include "vulkan/context.h"
#include "vulkan/scene_builder.h"
#include "vulkan/vk_fault_hook.h"

namespace rayspec {
namespace {

// Two instances of one triangle, compacted before an update that moves one.
Case copiedThenUpdated(const std::string& tlas_update) {
  return parsedCase(
      "rules: [R-AS-MEMORY]\n"
      "scene:\n"
      "  build: {copy: compact, order: [copy, update], tlas_update: " +
      tlas_update +
      "}\n"
      "  blas:\n"
      "    tri: [{triangles: {vertices: [[-1, -1, 0], [1, -1, 0], [-1, 1, 0]]}}]\n"
      "  instances: [{blas: tri}, {blas: tri, transform: {translate: [4, 0, 0]}}]\n"
      "  update:\n"
      "    blas: {tri: [{vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}]}\n"
      "    instances: [{instance: 1, transform: {translate: [0, 4, 0]}}]\n"
      "rays:\n"
      "  list: [{origin: [-0.5, -0.5, 1], direction: [0, 0, -1]}]\n"
      "pipeline:\n"
      "  miss: [[record: {hit: 0}]]\n"
      "  hit_groups: [{closest_hit: [record: [hit]]}]\n"
      "outputs:\n"
      "  per_ray: [hit]\n");
}

class RebuildAfterCopy : public LiveDevice {
 protected:
  // The accelerationStructureSize the device reports for a top level of
  // the case's instances, built with the case's flags and compaction.
  VkDeviceSize topLevelBuildSize(const Case& c) const {
    VkAccelerationStructureGeometryKHR g{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    g.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    g.geometry.instances.sType =
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
    VkAccelerationStructureBuildGeometryInfoKHR info{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
    info.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
    info.flags = c.scene.build.flags | kBuildAllowCompaction;
    info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    info.geometryCount = 1;
    info.pGeometries = &g;
    const uint32_t count = static_cast<uint32_t>(c.scene.instances.size());
    VkAccelerationStructureBuildSizesInfoKHR sizes{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    ctx_.fn.getAccelerationStructureBuildSizes(
        ctx_.device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info, &count, &sizes);
    return sizes.accelerationStructureSize;
  }
  // The top level the traces use and its size; the guards' findings in overruns_.
  BuiltStructure build(const Case& c, Cleanup& cleanup) {
    const Result<std::vector<BuiltStructure>> built =
        buildScene(ctx_, c.scene, 0, cleanup, overruns_, query_findings_);
    EXPECT_TRUE(built.ok()) << built.error().format();
    return built.ok() && built->size() == 1 ? built->front() : BuiltStructure{};
  }
  std::vector<std::string> overruns_;
  std::vector<DeviceFinding> query_findings_;
};

TEST_F(RebuildAfterCopy, ARebuildAfterACompactCopyWritesAStructureOfTheBuildSize) {
  const Case c = copiedThenUpdated("rebuild");
  Cleanup cleanup;
  const BuiltStructure traced = build(c, cleanup);
  EXPECT_EQ(traced.size, topLevelBuildSize(c));
  EXPECT_EQ(traced.name, "TLAS 0");
  EXPECT_TRUE(overruns_.empty()) << overruns_.front();
  cleanup.run();
  EXPECT_TRUE(ctx_.capture->take().empty());
}

// The control: updated in place, the compacted copy is what the traces use
// (its compacted size, no more than the build size).
TEST_F(RebuildAfterCopy, AnUpdateAfterACompactCopyUpdatesTheCopyInPlace) {
  const Case c = copiedThenUpdated("update");
  Cleanup cleanup;
  const BuiltStructure traced = build(c, cleanup);
  EXPECT_GT(traced.size, 0u);
  EXPECT_LE(traced.size, topLevelBuildSize(c));
  EXPECT_TRUE(overruns_.empty()) << overruns_.front();
  cleanup.run();
  EXPECT_TRUE(ctx_.capture->take().empty());
}

// build-writes-past-size overwrites the first guard (BLAS 0's) after the
// bottom levels' commands, here after their copy: the guard check at the
// end of that copy finds nothing, the next one names the commands after it.
TEST_F(RebuildAfterCopy, AWritePastASizeAfterTheCopyIsNotLaidOnTheCopy) {
  injectLayoutFault(LayoutFault::WritesPastSize);
  const Case c = copiedThenUpdated("rebuild");
  Cleanup cleanup;
  build(c, cleanup);
  ASSERT_EQ(overruns_.size(), 1u);
  EXPECT_EQ(overruns_[0].rfind("BLAS 0, its accelerationStructureSize (", 0), 0u) << overruns_[0];
  EXPECT_NE(overruns_[0].find("guard bytes after it changed after the copy of the bottom levels, "
                              "by the end of the copy of the top levels"),
            std::string::npos)
      << overruns_[0];
}

}  // namespace
}  // namespace rayspec
