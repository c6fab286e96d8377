// The required-limits check (vulkan/required_limits.h) on made-up devices:
// the specification's own values pass, one step beyond each fails, and the
// limits a device's extensions or features do not bring are not judged.
#include <gtest/gtest.h>

#include <string>

#include "vulkan/required_limits.h"

namespace rayspec {
namespace {

// A device reporting exactly what the specification requires.
DeviceInfo specMinimumDevice() {
  DeviceInfo d;
  d.ray_tracing_extension = d.acceleration_structure_extension = true;
  d.acceleration_structure_update_after_bind = true;
  d.shader_group_handle_size = 32;
  d.max_ray_recursion_depth = 1;
  d.max_shader_group_stride = 4096;
  d.shader_group_base_alignment = 64;
  d.shader_group_handle_capture_replay_size = 64;
  d.max_ray_dispatch_invocation_count = 1u << 30;
  d.shader_group_handle_alignment = 32;
  d.max_ray_hit_attribute_size = 32;
  d.max_geometry_count = d.max_instance_count = (1u << 24) - 1;
  d.max_primitive_count = (1u << 29) - 1;
  d.max_per_stage_descriptor_acceleration_structures = 16;
  d.max_per_stage_descriptor_update_after_bind_acceleration_structures = 500000;
  d.max_descriptor_set_acceleration_structures = 16;
  d.max_descriptor_set_update_after_bind_acceleration_structures = 500000;
  d.min_acceleration_structure_scratch_offset_alignment = 256;
  return d;
}

const LimitCheck& checkNamed(const std::vector<LimitCheck>& checks, const std::string& name) {
  for (const LimitCheck& c : checks)
    if (c.name == name) return c;
  static const LimitCheck none{"(none)"};
  ADD_FAILURE() << name << " is not checked";
  return none;
}

TEST(RequiredLimits, TheSpecificationsOwnValuesPass) {
  const std::vector<LimitCheck> checks = checkRequiredLimits(specMinimumDevice());
  EXPECT_EQ(checks.size(), 16u);
  for (const LimitCheck& c : checks) {
    EXPECT_TRUE(c.applies) << c.name;
    EXPECT_TRUE(c.ok) << c.name << ": " << c.value << ", " << c.requirement;
  }
}

TEST(RequiredLimits, OneStepBeyondEachBoundFails) {
  DeviceInfo d = specMinimumDevice();
  d.max_primitive_count -= 1;                                  // a minimum
  d.shader_group_base_alignment = 128;                         // a maximum
  d.shader_group_handle_size = 16;                             // an exact value
  d.min_acceleration_structure_scratch_offset_alignment = 96;  // not a power of two
  const std::vector<LimitCheck> checks = checkRequiredLimits(d);
  EXPECT_FALSE(checkNamed(checks, "maxPrimitiveCount").ok);
  EXPECT_EQ(checkNamed(checks, "maxPrimitiveCount").requirement, "at least 536870911");
  EXPECT_FALSE(checkNamed(checks, "shaderGroupBaseAlignment").ok);
  EXPECT_FALSE(checkNamed(checks, "shaderGroupHandleSize").ok);
  EXPECT_FALSE(checkNamed(checks, "minAccelerationStructureScratchOffsetAlignment").ok);
  int failing = 0;
  for (const LimitCheck& c : checks) failing += !c.ok;
  EXPECT_EQ(failing, 4);
  EXPECT_EQ(checkNamed(checks, "maxPrimitiveCount").caseName(), "limits/maxPrimitiveCount");
}

// Footnote 9: without the UpdateAfterBind feature those limits may be 0;
// with it, each is at least its ordinary counterpart.
TEST(RequiredLimits, UpdateAfterBindLimitsFollowTheFeature) {
  DeviceInfo d = specMinimumDevice();
  d.acceleration_structure_update_after_bind = false;
  d.max_per_stage_descriptor_update_after_bind_acceleration_structures = 0;
  const LimitCheck off = checkNamed(checkRequiredLimits(d),
                                    "maxPerStageDescriptorUpdateAfterBindAccelerationStructures");
  EXPECT_FALSE(off.applies);
  EXPECT_TRUE(off.ok);
  d = specMinimumDevice();
  d.max_per_stage_descriptor_acceleration_structures = 600000;
  const LimitCheck below = checkNamed(checkRequiredLimits(d),
                                      "maxPerStageDescriptorUpdateAfterBindAccelerationStructures");
  EXPECT_FALSE(below.ok);
  EXPECT_NE(below.requirement.find("maxPerStageDescriptorAccelerationStructures (600000)"),
            std::string::npos);
}

TEST(RequiredLimits, ADeviceWithoutTheExtensionsIsNotJudged) {
  DeviceInfo d;  // every value 0
  for (const LimitCheck& c : checkRequiredLimits(d)) {
    EXPECT_FALSE(c.applies) << c.name;
    EXPECT_TRUE(c.ok) << c.name;
  }
}

}  // namespace
}  // namespace rayspec
