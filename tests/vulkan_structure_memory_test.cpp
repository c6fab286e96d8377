// scene.build.generic and scene.build.sparse take effect (vulkan/build_log.h):
// each structure created GENERIC where its level is named, and every build
// still naming its real type; every structure and the scratch in a buffer
// created with SPARSE_BINDING, bound by vkQueueBindSparse page by page out
// of order, each structure across a page boundary; scene.build.storage
// places them in shared buffers (and reused over a decoy's memory, with
// another structure created over each). The traces see the same
// scene, with the validation layer silent. Without sparseBinding, or a
// queue that binds sparse memory, the case is NotSupported naming it.
#include <gtest/gtest.h>

#include <map>

#include "parse_support.h"
#include "plan/plan.h"
#include "results/record_layout.h"
#include "vulkan/build_log.h"
#include "vulkan/context.h"
#include "vulkan/run_case.h"
#include "vulkan/vk_fault_hook.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {
namespace {

// Two BLASes (triangles and boxes) and a top level, updated and compacted:
// the structures as built (updated in place) and their copies, both levels.
Case updatedAndCompacted(const std::string& build) {
  return parsedCase(
      "rules: [R-AS-UPDATE]\n"
      "scene:\n"
      "  build: {copy: compact, order: [update, copy], " +
      build +
      "}\n"
      "  blas:\n"
      "    tri: [{triangles: {vertices: [[-1, -1, 0], [1, -1, 0], [-1, 1, 0]]}}]\n"
      "    box: [{aabbs: [[-1, -1, -0.5, 1, 1, 0.5]]}]\n"
      "  instances:\n"
      "    - {blas: tri}\n"
      "    - {blas: box, sbt_offset: 1, transform: {translate: [10, 0, 0]}}\n"
      "  update:\n"
      "    blas: {tri: [{vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}]}\n"
      "rays:\n"
      "  list: [{origin: [-0.5, -0.25, 1], direction: [0, 0, -1]},\n"
      "         {origin: [10, 0, 1], direction: [0, 0, -1]}]\n"
      "pipeline:\n"
      "  miss: [[record: {hit: 0}]]\n"
      "  hit_groups:\n"
      "    - closest_hit: [record: {hit: 1}]\n"
      "    - intersection: [report: {t: 1, kind: 0}]\n"
      "      closest_hit: [record: {hit: 2}]\n"
      "outputs:\n"
      "  per_ray: [hit]\n");
}

struct StructureRun : testing::Test {
  void SetUp() override {
    Result<std::unique_ptr<VulkanEngine>> made = VulkanEngine::create(VulkanOptions{});
    if (!made) GTEST_SKIP() << made.error().format();
    engine = std::move(*made);
    recordBuildLog(true);
  }
  void TearDown() override { recordBuildLog(false); }

  // The case run with the validation layer on: it must pass untroubled,
  // the first ray hitting the updated triangle (1), the second the box (2).
  void runClean(const Case& c) {
    ASSERT_TRUE(engine->validationEnabled()) << "VK_LAYER_KHRONOS_validation is installed here";
    const Results r = engine->run(c, derivePlan(c));
    ASSERT_TRUE(r.ok()) << r.statusText();
    EXPECT_TRUE(r.validation_messages.empty()) << r.validation_messages.front();
    EXPECT_TRUE(r.device_findings.empty()) << r.device_findings.front().message;
    const RecordField* hit = findRecordField("hit");
    ASSERT_EQ(r.records.size(), 2u * recordWords());
    EXPECT_EQ(r.records[hit->offset], 1u);
    EXPECT_EQ(r.records[recordWords() + hit->offset], 2u);
  }
  std::unique_ptr<VulkanEngine> engine;
};

constexpr VkAccelerationStructureTypeKHR kBottom = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
constexpr VkAccelerationStructureTypeKHR kTop = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
constexpr VkAccelerationStructureTypeKHR kGeneric = VK_ACCELERATION_STRUCTURE_TYPE_GENERIC_KHR;

TEST_F(StructureRun, GenericLevelsAreCreatedGenericAndBuiltWithTheirOwnType) {
  for (const char* levels : {"none", "bottom", "top", "both"}) {
    SCOPED_TRACE(levels);
    recordBuildLog(true);
    runClean(updatedAndCompacted(std::string("generic: ") + levels));
    const BuildLog& log = *buildLog();
    const std::string named = levels;
    std::map<VkAccelerationStructureKHR, VkAccelerationStructureTypeKHR> level_of;
    size_t generic = 0, per_level[2] = {0, 0};
    for (const LoggedStructure& s : log.structures) {
      const bool bottom = s.level == kBottom;
      ASSERT_TRUE(bottom || s.level == kTop);
      const bool asked = named == "both" || named == (bottom ? "bottom" : "top");
      EXPECT_EQ(s.created, asked ? kGeneric : s.level);
      generic += s.created == kGeneric;
      ++per_level[bottom];
      level_of[s.handle] = s.level;
    }
    // Each level: the built structures and their compacted copies.
    EXPECT_EQ(per_level[1], 4u);
    EXPECT_EQ(per_level[0], 2u);
    EXPECT_EQ(generic, named == "none" ? 0u : named == "bottom" ? 4u : named == "top" ? 2u : 6u);
    // Builds and updates: 2 BLASes and the TLAS, each built then updated.
    ASSERT_EQ(log.builds.size(), 6u);
    for (const LoggedBuild& b : log.builds) {
      ASSERT_TRUE(level_of.count(b.dst));
      EXPECT_EQ(b.type, level_of[b.dst]);  // never GENERIC
    }
    EXPECT_TRUE(log.sparse.empty());
  }
}

TEST_F(StructureRun, SparseStructuresAndScratchAreBoundPageByPageAcrossPages) {
  runClean(updatedAndCompacted("sparse: [structures, scratch]"));
  const BuildLog& log = *buildLog();
  ASSERT_EQ(log.structures.size(), 6u);
  // Six structures and one scratch buffer, each its own sparse buffer.
  ASSERT_EQ(log.sparse.size(), 7u);
  for (const LoggedSparseBuffer& s : log.sparse) {
    EXPECT_TRUE(s.flags & VK_BUFFER_CREATE_SPARSE_BINDING_BIT);
    EXPECT_GT(s.page, 0u);
    EXPECT_EQ(s.binds, s.size / s.page);
  }
  for (const LoggedStructure& s : log.structures) {
    ASSERT_GT(s.page, 0u);
    EXPECT_LT(s.offset, s.page);  // starts on the first page ...
    if (s.size > 256) {
      EXPECT_GT(s.offset + s.size, s.page) << s.size;  // ... ends on another
    }
    EXPECT_EQ(s.offset % 256, 0u);
  }
  // Every structure's buffer holds two pages or more, from two allocations
  // out of order.
  for (size_t i = 0; i < log.sparse.size(); ++i) {
    if (log.sparse[i].binds < 2) continue;
    EXPECT_EQ(log.sparse[i].allocations, 2u) << i;
    EXPECT_FALSE(log.sparse[i].in_order) << i;
  }
  size_t many = 0;
  for (const LoggedSparseBuffer& s : log.sparse) many += s.binds > 1;
  EXPECT_GE(many, log.structures.size());
}

// scene.build.storage shared: the six structures (and copies) one after
// another in one buffer, each at a multiple of 256 bytes, its guard before
// the next (R-AS-MEMORY holds: runClean finds no overrun).
TEST_F(StructureRun, SharedStorageStructuresLieInOneBufferAt256ByteOffsets) {
  runClean(updatedAndCompacted("storage: shared"));
  const BuildLog& log = *buildLog();
  ASSERT_EQ(log.structures.size(), 6u);
  std::map<VkBuffer, std::vector<const LoggedStructure*>> in;
  for (const LoggedStructure& s : log.structures) {
    EXPECT_EQ(s.offset % 256, 0u);
    in[s.buffer].push_back(&s);
  }
  ASSERT_EQ(in.size(), 1u);  // small structures: all in the arena's first buffer
  const std::vector<const LoggedStructure*>& all = in.begin()->second;
  for (size_t i = 1; i < all.size(); ++i)
    EXPECT_GE(all[i]->offset, all[i - 1]->offset + all[i - 1]->size + 256) << i;
}

// scene.build.storage reused: the decoy (two BLASes and the top level, no
// copy) first, the scene's six structures over its memory (the first at the
// decoy's first offset of the same buffer), then one more structure created
// over each of the six, never built; the traces see the scene alone.
TEST_F(StructureRun, ReusedStorageBuildsOverADecoyAndCreatesOverEachStructure) {
  runClean(updatedAndCompacted("storage: reused"));
  const BuildLog& log = *buildLog();
  ASSERT_EQ(log.structures.size(), 3u + 6u + 6u);
  const LoggedStructure &decoy = log.structures[0], &first = log.structures[3];
  EXPECT_EQ(first.buffer, decoy.buffer);
  EXPECT_EQ(first.offset, decoy.offset);
  std::map<VkAccelerationStructureKHR, bool> built;
  for (const LoggedBuild& b : log.builds) built[b.dst] = true;
  for (size_t i = 0; i < 6; ++i) {
    const LoggedStructure &s = log.structures[3 + i], &over = log.structures[9 + i];
    EXPECT_EQ(over.buffer, s.buffer) << i;
    EXPECT_EQ(over.offset, s.offset) << i;
    EXPECT_EQ(over.size, s.size) << i;
    EXPECT_EQ(over.created, s.created) << i;
    EXPECT_FALSE(built.count(over.handle)) << i;
  }
}

// scene.build.sparse instances and geometry: the input buffer and each
// state's instance buffer (as built, after the update) sparse, their
// contents on two pages from two allocations out of order; the rest bound
// whole (sparse: true binds all ten).
TEST_F(StructureRun, SparseInputsAreBoundPageByPageAcrossPages) {
  runClean(updatedAndCompacted("sparse: [instances, geometry]"));
  const BuildLog& log = *buildLog();
  ASSERT_EQ(log.sparse.size(), 3u);
  for (const LoggedSparseBuffer& s : log.sparse) {
    EXPECT_EQ(s.binds, 2u);
    EXPECT_EQ(s.allocations, 2u);
    EXPECT_FALSE(s.in_order);
  }
  for (const LoggedStructure& s : log.structures) EXPECT_EQ(s.page, 0u);
  recordBuildLog(true);
  runClean(updatedAndCompacted("sparse: true"));
  EXPECT_EQ(buildLog()->sparse.size(), 10u);
}

// The planted fault sparse-page-lost: the second page of a sparse input
// buffer bound elsewhere once filled, zeros there. Instances: the second
// instance (the box) lies on it and vanishes; geometry: the updated
// triangle's vertices lie on it (zeros: degenerate) and the first ray
// misses (the second meets a box cut to a point, which it may hit).
TEST_F(StructureRun, ALostPageOfSparseInputsChangesTheTraces) {
  injectLayoutFault(LayoutFault::SparsePageLost);
  const RecordField* hit = findRecordField("hit");
  for (const char* buffers : {"instances", "geometry"}) {
    SCOPED_TRACE(buffers);
    const Case c = updatedAndCompacted(std::string("sparse: [") + buffers + "]");
    const Results r = engine->run(c, derivePlan(c));
    ASSERT_TRUE(r.ok()) << r.statusText();
    ASSERT_EQ(r.records.size(), 2u * recordWords());
    const bool instances = std::string(buffers) == "instances";
    EXPECT_EQ(r.records[hit->offset], instances ? 1u : 0u);
    if (instances) {
      EXPECT_EQ(r.records[recordWords() + hit->offset], 0u);
    }
  }
  injectLayoutFault(LayoutFault::None);
}

// A device the engine never opens: what the support check reads.
TEST(StructureSupport, SparseWithoutTheFeatureOrTheQueueIsNotSupported) {
  const Case c = updatedAndCompacted("sparse: true");
  VulkanContext ctx;
  ctx.info.max_ray_recursion_depth = 31;
  for (uint64_t& size : ctx.info.max_launch_size) size = 1u << 16;
  ctx.info.max_ray_dispatch_invocation_count = 1u << 20;
  ctx.info.shader_group_handle_size = ctx.info.shader_group_handle_alignment = 32;
  ctx.info.shader_group_base_alignment = 64;
  ctx.info.max_shader_group_stride = 4096;
  ctx.info.sparse_binding = ctx.info.sparse_binding_queue = true;
  EXPECT_TRUE(checkCaseSupport(ctx, c, derivePlan(c)).ok());
  ctx.info.sparse_binding_queue = false;
  const Result<void> no_queue = checkCaseSupport(ctx, c, derivePlan(c));
  ASSERT_FALSE(no_queue);
  EXPECT_EQ(no_queue.error().kind, ErrorKind::NotSupported);
  EXPECT_NE(no_queue.error().message.find("VK_QUEUE_SPARSE_BINDING_BIT"), std::string::npos);
  ctx.info.sparse_binding = false;
  const Result<void> no_feature = checkCaseSupport(ctx, c, derivePlan(c));
  ASSERT_FALSE(no_feature);
  EXPECT_EQ(no_feature.error().message, "scene.build.sparse: the device lacks sparseBinding");
}

}  // namespace
}  // namespace rayspec
