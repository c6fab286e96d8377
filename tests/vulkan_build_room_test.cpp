// Builds::checkRoom (vulkan/build_batch.h): rayspec's own check of
// VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-10126, which the
// validation layer of 1.3.239 misses. A build (MODE_BUILD) into a
// destination without room for its accelerationStructureSize (a compacted
// copy, or a smaller structure) is refused, naming it; an update of a
// compacted copy, and a build with room, are not.
#include <gtest/gtest.h>

#include "vulkan/build_batch.h"

namespace rayspec {
namespace {

// One build of "TLAS 0" of 336 bytes in `mode` into a destination with `room`.
Builds oneBuild(VkBuildAccelerationStructureModeKHR mode, VkDeviceSize room) {
  Builds b;
  VkAccelerationStructureBuildGeometryInfoKHR info{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  info.mode = mode;
  b.add(info, nullptr, 0);
  b.names.push_back("TLAS 0");
  b.sizes.push_back(336);
  b.room.push_back(room);
  return b;
}

TEST(BuildRoom, ABuildIntoACompactedCopyIsRefused) {
  const Result<void> r = oneBuild(VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR, 0).checkRoom();
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::Harness);
  EXPECT_EQ(r.error().message,
            "a build of TLAS 0 into a structure with room for an update only (a compacted copy), "
            "less than its accelerationStructureSize 336 "
            "(VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-10126): a rayspec bug");
}

TEST(BuildRoom, ABuildIntoASmallerStructureIsRefused) {
  const Result<void> r = oneBuild(VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR, 335).checkRoom();
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("room for 335 bytes"), std::string::npos) << r.error().message;
}

TEST(BuildRoom, ABuildWithRoomAndAnUpdateOfACompactedCopyPass) {
  EXPECT_TRUE(oneBuild(VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR, 336).checkRoom().ok());
  EXPECT_TRUE(oneBuild(VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR, 0).checkRoom().ok());
}

}  // namespace
}  // namespace rayspec
