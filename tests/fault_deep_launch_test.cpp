// The faults of deep launches on builtins/launch-deep (counters only, every id
// tracing the same ray), the model's exact tier as the device: a device that
// reads gl_LaunchIDEXT.y and .z modulo 4096 (launch-id-yz-wrapped) or runs
// only the first z layer (launch-depth-lost) moves the counters, so the case
// fails; a launch the fault cannot touch is left alone and passes.
#include <gtest/gtest.h>

#include "planted_suite_case.h"

namespace rayspec {
namespace {

TEST(DeepLaunchFaults, IdsWrappedInYOrZFailTheLaunchesDeeperThan4096) {
  for (const char* name :
       {"builtins/launch-deep/trace_rays-1x16384x1", "builtins/launch-deep/indirect-1x1x16384"}) {
    const PlantedVerdict p = plantOnSuiteCase(name, "launch-id-yz-wrapped");
    EXPECT_TRUE(p.fault.applied) << name << ": " << p.fault.what;
    EXPECT_EQ(p.verdict.status, Status::Fail) << name << ": " << p.verdict.headline();
  }
}

TEST(DeepLaunchFaults, ALostDepthFailsALaunchOfIdsAllAlikeInZ) {
  const PlantedVerdict p =
      plantOnSuiteCase("builtins/launch-deep/indirect-1x1x16384", "launch-depth-lost");
  EXPECT_TRUE(p.fault.applied) << p.fault.what;
  EXPECT_EQ(p.verdict.status, Status::Fail) << p.verdict.headline();
}

TEST(DeepLaunchFaults, ALostDepthLeavesALaunchOfOneLayerAlone) {
  const PlantedVerdict p =
      plantOnSuiteCase("builtins/launch-deep/trace_rays-1x16384x1", "launch-depth-lost");
  EXPECT_FALSE(p.fault.applied) << p.fault.what;
  EXPECT_EQ(p.verdict.status, Status::Pass) << p.verdict.headline();
}

}  // namespace
}  // namespace rayspec
