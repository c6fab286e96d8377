// Tests of the case reader's image outputs: `equal_to` names another image
// of the case with the same texel format; errors name file, line and field.
#include <gtest/gtest.h>

#include "parse/parse_case.h"
#include "parse_support.h"

namespace rayspec {
namespace {

std::string caseWithImages(const std::string& images) {
  return R"(rules: [R-CALLABLE]
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
  instances:
    - {blas: tri}
rays:
  grid: {size: [2, 2], origin: [-1, -1, 1], du: [1, 0, 0], dv: [0, 1, 0], direction: [0, 0, -1]}
pipeline:
  miss:
    - [record: {hit: 0}]
  hit_groups:
    - closest_hit: [record: {color: [1.0, 0.0, 0.0, 1.0], color2: [1.0, 0.0, 0.0, 1.0], hit: 1}]
outputs:
  per_ray: [hit, color, color2]
  images:
)" + images;
}

ParseResult parseImages(const std::string& images) {
  return parseCaseText(caseWithImages(images), "t.yaml", "family/t");
}

TEST(ParseImages, EqualToNamesAnotherImage) {
  const ParseResult r =
      parseImages("    - {name: a, from: color}\n    - {name: b, from: color2, equal_to: a}\n");
  ASSERT_TRUE(r.value) << allErrors(r);
  EXPECT_EQ(r.value->outputs.images[1].equal_to, "a");
  EXPECT_TRUE(r.value->outputs.images[0].equal_to.empty());
}

TEST(ParseImages, EqualToAnUnknownImageOrItselfIsAnError) {
  for (const char* other : {"nope", "b"}) {
    const ParseResult r = parseImages(
        std::string("    - {name: a, from: color}\n    - {name: b, from: color2, equal_to: ") +
        other + "}\n");
    ASSERT_FALSE(r.value) << other;
    ASSERT_EQ(r.errors.size(), 1u) << allErrors(r);
    EXPECT_EQ(r.errors[0].loc.line, 20) << allErrors(r);
    EXPECT_GT(r.errors[0].loc.column, 0);
    EXPECT_EQ(r.errors[0].loc.field, "outputs.images[1].equal_to");
    EXPECT_NE(r.errors[0].message.find("is not another image"), std::string::npos) << allErrors(r);
  }
}

TEST(ParseImages, EqualToAnImageOfAnotherTexelFormatIsAnError) {
  const ParseResult r =
      parseImages("    - {name: a, from: hit}\n    - {name: b, from: color2, equal_to: a}\n");
  ASSERT_FALSE(r.value);
  EXPECT_NE(allErrors(r).find("different texel formats"), std::string::npos) << allErrors(r);
}

}  // namespace
}  // namespace rayspec
