// The box and instance grid generators (case/box_grid.h) and their case
// syntax: `aabbs: {grid: ...}` and a `scene.instances` entry `{grid: ...}`.
#include <gtest/gtest.h>

#include "case/box_grid.h"
#include "parse_support.h"

namespace rayspec {
namespace {

std::string gridCase(const std::string& aabbs, const std::string& instances) {
  return "rules: [R-AS-SIZE]\n"
         "scene:\n"
         "  blas:\n"
         "    boxes: [{aabbs: " +
         aabbs +
         "}]\n"
         "  instances:\n" +
         instances +
         "rays:\n"
         "  list: [{origin: [0, 0, 5], direction: [0, 0, -1], cull_mask: 3}]\n"
         "pipeline:\n"
         "  hit_groups: [{intersection: [report: {t: 1.0, kind: 0}]}]\n"
         "outputs:\n"
         "  per_ray: [hit]\n";
}

TEST(BoxGrid, RowMajorBoxesShareTheirFaces) {
  Geometry g;
  makeBoxGrid(3, 2, {6, 4}, {1, 0, 2}, 1, g);
  ASSERT_EQ(g.aabbs.size(), 6u);
  // Box 4 is cell (1, 1): x 0..2, y 0..2, z 1.5..2.5.
  EXPECT_EQ(g.aabbs[4], (std::array<float, 6>{0, 0, 1.5f, 2, 2, 2.5f}));
  for (uint32_t j = 0; j < 2; ++j)
    for (uint32_t i = 0; i + 1 < 3; ++i)
      EXPECT_EQ(g.aabbs[j * 3 + i][3], g.aabbs[j * 3 + i + 1][0]);  // bit for bit
}

TEST(BoxGrid, InstanceGridTranslatesAndNumbers) {
  const ParseResult r =
      parse(gridCase("{grid: {cells: [2, 2], size: [1, 1], height: 0.5}}",
                     "    - {blas: boxes, mask: 3}\n"
                     "    - grid: {cells: [3, 2], spacing: [2, 5], origin: [1, 1, 1], "
                     "instance: {blas: boxes, mask: 0x0C, sbt_offset: 1}}\n"));
  ASSERT_TRUE(r.value && r.errors.empty()) << allErrors(r);
  const Scene& s = r.value->scene;
  ASSERT_EQ(s.blases[0].geometries[0].aabbs.size(), 4u);
  ASSERT_EQ(s.instances.size(), 7u);      // the listed one, then the grid's six
  const Instance& last = s.instances[6];  // grid cell (2, 1)
  EXPECT_EQ(last.transform[3], 5.0f);
  EXPECT_EQ(last.transform[7], 6.0f);
  EXPECT_EQ(last.transform[11], 1.0f);
  EXPECT_EQ(last.custom_index, 5u);
  EXPECT_EQ(last.mask, 0x0Cu);
  EXPECT_EQ(last.sbt_offset, 1u);
  EXPECT_EQ(s.instances[0].mask, 3u);
}

TEST(BoxGrid, ErrorsNameTheField) {
  const ParseResult own = parse(gridCase(
      "[[0, 0, 0, 1, 1, 1]]",
      "    - grid: {cells: [2, 2], spacing: [1, 1], instance: {blas: boxes, custom_index: 3}}\n"));
  EXPECT_NE(firstError(own).find("scene.instances[0].grid.instance"), std::string::npos)
      << firstError(own);
  const ParseResult many = parse(
      gridCase("[[0, 0, 0, 1, 1, 1]]",
               "    - grid: {cells: [2048, 1024], spacing: [1, 1], instance: {blas: boxes}}\n"));
  EXPECT_NE(firstError(many).find("at most 2^20"), std::string::npos) << firstError(many);
  const ParseResult box =
      parse(gridCase("{grid: {cells: [2, 2], size: [1, 1]}}", "    - {blas: boxes}\n"));
  EXPECT_NE(firstError(box).find("height"), std::string::npos) << firstError(box);
}

}  // namespace
}  // namespace rayspec
