// R-AS-MEMORY: every structure, scratch region and copy is followed by a
// guard the builds must leave alone. On lavapipe the guards hold; a build
// made to write past its size (the layout fault build-writes-past-size) is
// named, with the region and the size the device reported.
#include <gtest/gtest.h>

#include "parse_support.h"
#include "plan/plan.h"
#include "vulkan/memory_guards.h"
#include "vulkan/vk_fault_hook.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {
namespace {

TEST(MemoryGuards, AGuardStartsAtTheFirstWordPastTheRegion) {
  EXPECT_EQ(guardOffset(0, 296), 296u);
  EXPECT_EQ(guardOffset(256, 297), 556u);  // 553 rounded up to a word
  EXPECT_EQ(guardedSize(297), 300u + kGuardBytes);
}

Case updatedAndCompacted() {
  return parsedCase(
      "rules: [R-AS-MEMORY]\n"
      "scene:\n"
      "  build: {copy: compact, order: [update, copy]}\n"
      "  blas:\n"
      "    tri: [{triangles: {vertices: [[-1, -1, 0], [1, -1, 0], [-1, 1, 0]]}}]\n"
      "  instances: [{blas: tri}]\n"
      "  update:\n"
      "    blas: {tri: [{vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}]}\n"
      "rays:\n"
      "  list: [{origin: [-0.5, -0.5, 1], direction: [0, 0, -1]}]\n"
      "pipeline:\n"
      "  miss: [[record: {hit: 0}]]\n"
      "  hit_groups: [{closest_hit: [record: [hit]]}]\n"
      "outputs:\n"
      "  per_ray: [hit]\n");
}

struct GuardRun : testing::Test {
  void SetUp() override {
    VulkanOptions options;
    options.validation = false;
    Result<std::unique_ptr<VulkanEngine>> made = VulkanEngine::create(options);
    if (!made) GTEST_SKIP() << made.error().format();
    engine = std::move(*made);
  }
  void TearDown() override { injectLayoutFault(LayoutFault::None); }
  std::unique_ptr<VulkanEngine> engine;
};

TEST_F(GuardRun, EveryGuardHoldsOnACorrectBuild) {
  const Case c = updatedAndCompacted();
  const Results r = engine->run(c, derivePlan(c));
  ASSERT_TRUE(r.ok()) << r.statusText();
  EXPECT_TRUE(r.device_findings.empty()) << r.device_findings.front().message;
}

TEST_F(GuardRun, AWritePastTheReportedSizeIsNamed) {
  injectLayoutFault(LayoutFault::WritesPastSize);
  const Case c = updatedAndCompacted();
  const Results r = engine->run(c, derivePlan(c));
  ASSERT_TRUE(r.ok()) << r.statusText();
  ASSERT_EQ(r.device_findings.size(), 1u);
  EXPECT_EQ(r.device_findings[0].rule, "R-AS-MEMORY");
  EXPECT_NE(r.device_findings[0].message.find("BLAS 0, its accelerationStructureSize ("),
            std::string::npos)
      << r.device_findings[0].message;
  EXPECT_NE(r.device_findings[0].message.find("4 of the 256 guard bytes"), std::string::npos)
      << r.device_findings[0].message;
}

}  // namespace
}  // namespace rayspec
