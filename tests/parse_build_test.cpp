// scene.build (R-AS-COPY): the build flags and the copy a case asks for;
// scene.update (R-AS-UPDATE): the scene after the update and the one first
// built; each error at its line and field.
#include <gtest/gtest.h>

#include "case/flag_names.h"
#include "parse/parse_case.h"
#include "parse_support.h"

namespace rayspec {
namespace {

ParseResult parseBuild(const std::string& build) {
  return parseCaseText(oneTriangleText("R-AS-COPY", build, ""), "t.yaml", "t/t");
}

TEST(SceneBuild, DefaultsToPreferFastTraceWithoutCopy) {
  const ParseResult r = parseBuild("{}");
  ASSERT_TRUE(r.value) << firstError(r);
  EXPECT_EQ(r.value->scene.build.flags, kBuildPreferFastTrace);
  EXPECT_EQ(r.value->scene.build.copy, AsCopy::None);
}

TEST(SceneBuild, FlagsAndCopyAreRead) {
  const ParseResult r = parseBuild("{flags: [prefer_fast_build, low_memory], copy: compact}");
  ASSERT_TRUE(r.value) << firstError(r);
  EXPECT_EQ(r.value->scene.build.flags, kBuildPreferFastBuild | kBuildLowMemory);
  EXPECT_EQ(r.value->scene.build.copy, AsCopy::Compact);
  EXPECT_STREQ(asCopyName(AsCopy::Clone), "clone");
}

TEST(SceneBuild, ErrorsNameTheLineAndField) {
  struct Bad {
    std::string build, field, message;
  } bad[] = {{"{copy: deserialize}", "scene.build.copy",
              "unknown copy 'deserialize' (none, clone, compact, serialize)"},
             {"{flags: [prefer_fast_trace, prefer_fast_build]}", "scene.build.flags",
              "prefer_fast_trace and prefer_fast_build together"},
             {"{flags: [fastest]}", "scene.build.flags", "fastest"},
             {"{copies: clone}", "scene.build", "unknown key 'copies'"},
             {"{command: cpu}", "scene.build.command",
              "unknown build command 'cpu' (device, indirect, host)"},
             {"{generic: middle}", "scene.build.generic",
              "unknown levels 'middle' (none, bottom, top, both)"},
             {"{sparse: yes please}", "scene.build.sparse",
              "unknown buffer 'yes please' (true, false, all, none, structures, scratch, "
              "instances, geometry)"},
             {"{sparse: [scratch, vertices]}", "scene.build.sparse", "unknown buffer 'vertices'"}};
  for (const Bad& b : bad) {
    const ParseResult r = parseBuild(b.build);
    EXPECT_FALSE(r.value) << b.build;
    const std::string e = firstError(r);
    EXPECT_NE(e.find("t.yaml:3"), std::string::npos) << e;
    EXPECT_NE(e.find(b.field), std::string::npos) << e;
    EXPECT_NE(e.find(b.message), std::string::npos) << e;
  }
}

TEST(SceneBuild, LayoutFieldsAreRead) {
  const ParseResult r = parseBuild(
      "{instances_as_pointers: true, data_offsets: true, first_vertex: 3, vertex_stride: 20, "
      "aabb_stride: 32}");
  ASSERT_TRUE(r.value) << firstError(r);
  const AsBuild& b = r.value->scene.build;
  EXPECT_TRUE(b.instances_as_pointers);
  EXPECT_TRUE(b.data_offsets);
  EXPECT_EQ(b.first_vertex, 3u);
  EXPECT_EQ(b.vertex_stride, 20u);
  EXPECT_EQ(b.aabb_stride, 32u);
  EXPECT_TRUE(b.customLayout());
  EXPECT_FALSE(parseBuild("{}").value->scene.build.customLayout());
}

TEST(SceneBuild, OneByOneAndUpdateIntoAreRead) {
  const ParseResult r = parseBuild("{one_by_one: true, update_into: other, tlas_update: rebuild}");
  ASSERT_TRUE(r.value) << firstError(r);
  EXPECT_TRUE(r.value->scene.build.tlas_rebuilt);
  EXPECT_TRUE(r.value->scene.build.one_by_one);
  EXPECT_TRUE(r.value->scene.build.update_into_other);
  EXPECT_FALSE(parseBuild("{update_into: same}").value->scene.build.update_into_other);
  for (const char* bad : {"{update_into: elsewhere}", "{update_into: other, copy: clone}",
                          "{one_by_one: 1}", "{tlas_update: refit}"}) {
    const ParseResult b = parseBuild(bad);
    EXPECT_FALSE(b.value) << bad;
    EXPECT_NE(firstError(b).find("scene.build."), std::string::npos) << firstError(b);
  }
}

TEST(SceneBuild, StorageIsRead) {
  EXPECT_EQ(parseBuild("{}").value->scene.build.storage, StructureStorage::Own);
  EXPECT_EQ(parseBuild("{storage: shared}").value->scene.build.storage, StructureStorage::Shared);
  EXPECT_EQ(parseBuild("{storage: reused}").value->scene.build.storage, StructureStorage::Reused);
  expectError(parseBuild("{storage: pooled}"), 3, "scene.build.storage",
              "unknown storage 'pooled' (own, shared, reused)");
  expectError(parseBuild("{sparse: true, storage: shared}"), 3, "scene.build.storage",
              "not combined with scene.build.sparse structures");
  const ParseResult inputs = parseBuild("{sparse: [geometry], storage: shared}");
  EXPECT_TRUE(inputs.value) << firstError(inputs);
}

TEST(SceneBuild, GenericAndSparseAreRead) {
  const ParseResult r = parseBuild("{generic: top, sparse: true}");
  ASSERT_TRUE(r.value) << firstError(r);
  EXPECT_EQ(r.value->scene.build.generic, GenericLevels::Top);
  EXPECT_TRUE(r.value->scene.build.sparse.all());
  const ParseResult none = parseBuild("{}");
  EXPECT_EQ(none.value->scene.build.generic, GenericLevels::None);
  EXPECT_FALSE(none.value->scene.build.sparse.any());
  EXPECT_TRUE(parseBuild("{sparse: all}").value->scene.build.sparse.all());
  EXPECT_FALSE(parseBuild("{sparse: false}").value->scene.build.sparse.any());
  const SparseBuffers two = parseBuild("{sparse: [scratch, instances]}").value->scene.build.sparse;
  EXPECT_TRUE(two.scratch && two.instances);
  EXPECT_FALSE(two.structures || two.geometry);
  const SparseBuffers one = parseBuild("{sparse: geometry}").value->scene.build.sparse;
  EXPECT_TRUE(one.geometry);
  EXPECT_FALSE(one.structures || one.scratch || one.instances);
  EXPECT_EQ(parseBuild("{generic: both}").value->scene.build.generic, GenericLevels::Both);
}

// A stride that does not fit the float3 vertices (12 bytes, 4 a component)
// or a box (24 bytes, a multiple of 8) is refused at its field.
TEST(SceneBuild, LayoutErrorsNameTheField) {
  struct Bad {
    std::string build, field, message;
  } bad[] = {{"{vertex_stride: 8}", "scene.build.vertex_stride", "does not fit float3"},
             {"{vertex_stride: 14}", "scene.build.vertex_stride", "a multiple of 4"},
             {"{aabb_stride: 28}", "scene.build.aabb_stride", "a multiple of 8"},
             {"{aabb_stride: 16}", "scene.build.aabb_stride", "at least 24"},
             {"{vertex_stride: 2048}", "scene.build.vertex_stride", ""},
             {"{first_vertex: 17}", "scene.build.first_vertex", ""},
             {"{data_offsets: yes}", "scene.build.data_offsets", "true or false"}};
  for (const Bad& b : bad) {
    const ParseResult r = parseBuild(b.build);
    EXPECT_FALSE(r.value) << b.build;
    const std::string e = firstError(r);
    EXPECT_NE(e.find(b.field), std::string::npos) << e;
    EXPECT_NE(e.find(b.message), std::string::npos) << e;
  }
}

ParseResult parseUpdate(const std::string& update, const std::string& build = "") {
  return parseCaseText(
      "rules: [R-AS-UPDATE]\n"
      "scene:\n"
      "  build: {" +
          build +
          "}\n"
          "  blas:\n"
          "    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]\n"
          "  instances: [{blas: t}, {blas: t, sbt_offset: 1}]\n"
          "  update: " +
          update +
          "\n"
          "rays:\n"
          "  list: [{origin: [0.2, 0.2, 1], direction: [0, 0, -1]}]\n"
          "pipeline:\n"
          "  hit_groups: [{closest_hit: [record: [hit]]}, {closest_hit: [record: [hit]]}]\n"
          "outputs:\n"
          "  per_ray: [hit]\n",
      "t.yaml", "t/t");
}

TEST(SceneUpdate, TheSceneIsAfterTheUpdateAndBuiltHoldsTheFirstBuild) {
  const ParseResult r = parseUpdate(
      "{blas: {t: [{vertices: [[0, 0, 1], [1, 0, 1], [0, 1, 1]]}]}, instances: [{instance: 1, "
      "transform: {translate: [5, 0, 0]}, mask: 3}]}");
  ASSERT_TRUE(r.value) << firstError(r);
  const Scene& after = r.value->scene;
  ASSERT_EQ(after.updates(), 1u);
  EXPECT_EQ(after.blases[0].geometries[0].vertices[0][2], 1.0f);
  EXPECT_EQ(after.earlier.front()->blases[0].geometries[0].vertices[0][2], 0.0f);
  EXPECT_EQ(after.instances[1].mask, 3u);
  EXPECT_EQ(after.instances[1].sbt_offset, 1u);  // kept
  EXPECT_EQ(after.instances[1].blas, after.earlier.front()->instances[1].blas);
  EXPECT_EQ(after.earlier.front()->instances[1].mask, 0xFFu);
  EXPECT_TRUE(after.build.flags & kBuildAllowUpdate);
  EXPECT_TRUE(after.earlier.front()->build.flags & kBuildAllowUpdate);
}

TEST(SceneUpdate, ErrorsNameTheLineAndField) {
  struct Bad {
    std::string update, field, message;
  } bad[] = {
      {"{blas: {t: [{vertices: [[0, 0, 1]]}]}}", "scene.update.blas.t[0].vertices",
       "1 entries, but the geometry was built with 3"},
      {"{blas: {u: [{}]}}", "scene.update.blas.u", "unknown BLAS 'u'"},
      {"{blas: {t: [{}, {}]}}", "scene.update.blas.t", "the BLAS has 1 geometries"},
      {"{instances: [{instance: 2, mask: 1}]}", "scene.update.instances[0].instance",
       "but the scene has 2"},
      {"{instances: [{instance: 0, blas: t}]}", "scene.update.instances[0]", "unknown key 'blas'"}};
  for (const Bad& b : bad) {
    const ParseResult r = parseUpdate(b.update);
    EXPECT_FALSE(r.value) << b.update;
    const std::string e = firstError(r);
    EXPECT_NE(e.find("t.yaml:7"), std::string::npos) << e;
    EXPECT_NE(e.find(b.field), std::string::npos) << e;
    EXPECT_NE(e.find(b.message), std::string::npos) << e;
  }
}

// R-AS-UPDATE: an update may move an inactive primitive's other coordinates,
// and make a triangle degenerate, but may not change which primitives are
// inactive (VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-03663, -03664).
TEST(SceneUpdate, AnUpdateKeepsWhichPrimitivesAreInactive) {
  const ParseResult made_inactive =
      parseUpdate("{blas: {t: [{vertices: [[.nan, 0, 1], [1, 0, 1], [0, 1, 1]]}]}}");
  expectError(made_inactive, 7, "scene.update.blas.t[0].vertices",
              "triangle 0 was active and the update makes it inactive");
  const ParseResult degenerate =
      parseUpdate("{blas: {t: [{vertices: [[0, 0, 1], [1, 0, 1], [2, 0, 1]]}]}}");
  EXPECT_TRUE(degenerate.value) << firstError(degenerate);
  const std::string text =
      "rules: [R-AS-UPDATE]\n"
      "scene:\n"
      "  blas:\n"
      "    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [.nan, 1, 0]],\n"
      "                     indices: [0, 1, 2, 2, 1, 3]}}]\n"
      "    b: [{aabbs: [[.nan, 0, 0, 1, 1, 1], [0, 0, 0, 1, 1, 1]]}]\n"
      "  instances: [{blas: t}, {blas: b}]\n"
      "  update: {blas: {t: [{vertices: [[0, 0, 1], [1, 0, 1], [0, 1, 1], [UPDATED]]}], "
      "b: [{aabbs: [BOXES]}]}}\n"
      "rays:\n"
      "  list: [{origin: [0.2, 0.2, 1], direction: [0, 0, -1]}]\n"
      "pipeline:\n"
      "  hit_groups: [{closest_hit: [record: [hit]]}]\n"
      "outputs:\n"
      "  per_ray: [hit]\n";
  auto with = [&text](const std::string& vertex, const std::string& boxes) {
    std::string t = text;
    t.replace(t.find("UPDATED"), 7, vertex);
    t.replace(t.find("BOXES"), 5, boxes);
    return parseCaseText(t, "t.yaml", "t/t");
  };
  const ParseResult kept = with(".nan, 5, 5", "[.nan, 2, 2, 3, 3, 3], [1, 1, 1, 1, 1, 1]");
  EXPECT_TRUE(kept.value) << firstError(kept);
  expectError(with("0, 1, 0", "[.nan, 0, 0, 1, 1, 1], [0, 0, 0, 1, 1, 1]"), 8,
              "scene.update.blas.t[0].vertices",
              "triangle 1 was inactive (NaN X) and the update makes it active");
  expectError(with(".nan, 1, 0", "[0, 0, 0, 1, 1, 1], [0, 0, 0, 1, 1, 1]"), 8,
              "scene.update.blas.b[0].aabbs", "box 0 was inactive");
}

TEST(SceneUpdate, AListUpdatesInTurnAndKeepsEveryState) {
  const ParseResult r = parseUpdate(
      "[{blas: {t: [{vertices: [[0, 0, 1], [1, 0, 1], [0, 1, 1]]}]}}, "
      "{instances: [{instance: 1, mask: 3}]}, "
      "{blas: {t: [{vertices: [[0, 0, 2], [1, 0, 2], [0, 1, 2]]}]}}]",
      "copy: clone, order: [update, copy, update, update]");
  ASSERT_TRUE(r.value) << firstError(r);
  const Scene& s = r.value->scene;
  ASSERT_EQ(s.updates(), 3u);
  EXPECT_EQ(s.earlier[0]->blases[0].geometries[0].vertices[0][2], 0.0f);
  EXPECT_EQ(s.earlier[1]->blases[0].geometries[0].vertices[0][2], 1.0f);
  EXPECT_EQ(s.earlier[1]->instances[1].mask, 0xFFu);
  EXPECT_EQ(s.earlier[2]->instances[1].mask, 3u);  // the second update's
  EXPECT_EQ(s.blases[0].geometries[0].vertices[0][2], 2.0f);
  EXPECT_EQ(s.instances[1].mask, 3u);  // kept by the third
  EXPECT_EQ(s.updatesBeforeCopy(), 1u);
  for (const auto& e : s.earlier) EXPECT_TRUE(e->earlier.empty());
  // Without an order: every update, then the copy.
  const ParseResult d = parseUpdate("[{}, {}]", "copy: compact");
  ASSERT_TRUE(d.value) << firstError(d);
  EXPECT_EQ(d.value->scene.updatesBeforeCopy(), 2u);
}

TEST(SceneUpdate, AnOrderNamesEachUpdateAndTheCopyOnce) {
  struct Bad {
    std::string update, build, field, message;
  } bad[] = {{"[{}, {}]", "copy: clone, order: [update, copy]", "scene.build.order",
              "names 1 update(s) and 1 copy, but the scene has 2 update(s)"},
             {"[{}]", "order: [update, copy]", "scene.build.order", "no copy (scene.build.copy)"},
             {"[{}]", "copy: clone, order: [update]", "scene.build.order", "one copy"},
             {"[{}]", "copy: clone, order: [update, clone]", "scene.build.order[1]",
              "unknown step 'clone'"},
             {"[{}]", "copy: serialize, order: [copy, update]", "scene.build.order",
              "an update after a serialize copy"},
             {"[]", "", "scene.update", "0 updates: a list holds 1 to 4"},
             {"[{}, {}, {}, {}, {}]", "", "scene.update", "5 updates"},
             {"[{}, {blas: {u: [{}]}}]", "", "scene.update[1].blas.u", "unknown BLAS 'u'"}};
  for (const Bad& b : bad) {
    const ParseResult r = parseUpdate(b.update, b.build);
    EXPECT_FALSE(r.value) << b.update << " / " << b.build;
    const std::string e = firstError(r);
    EXPECT_NE(e.find(b.field), std::string::npos) << e;
    EXPECT_NE(e.find(b.message), std::string::npos) << e;
  }
}

TEST(SceneBuild, TheBuildCommandIsRead) {
  EXPECT_EQ(parseBuild("{}").value->scene.build.command, BuildCommand::Device);
  EXPECT_EQ(parseBuild("{command: indirect}").value->scene.build.command, BuildCommand::Indirect);
  EXPECT_EQ(parseBuild("{command: host}").value->scene.build.command, BuildCommand::Host);
}

}  // namespace
}  // namespace rayspec
