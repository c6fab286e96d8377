// Tests of the case reader's image outputs: `equal_to` names another image
// of the case with the same texel format; errors name file, line and field.
#include <gtest/gtest.h>

#include "case/parse_case.h"

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

ParseResult parse(const std::string& images) {
  return parseCaseText(caseWithImages(images), "t.yaml", "family/t");
}

std::string errors(const ParseResult& r) {
  std::string s;
  for (const Error& e : r.errors) s += e.format() + "\n";
  return s;
}

TEST(ParseImages, EqualToNamesAnotherImage) {
  const ParseResult r =
      parse("    - {name: a, from: color}\n    - {name: b, from: color2, equal_to: a}\n");
  ASSERT_TRUE(r.value) << errors(r);
  EXPECT_EQ(r.value->outputs.images[1].equal_to, "a");
  EXPECT_TRUE(r.value->outputs.images[0].equal_to.empty());
}

TEST(ParseImages, EqualToAnUnknownImageOrItselfIsAnError) {
  for (const char* other : {"nope", "b"}) {
    const ParseResult r = parse(
        std::string("    - {name: a, from: color}\n    - {name: b, from: color2, equal_to: ") +
        other + "}\n");
    ASSERT_FALSE(r.value) << other;
    ASSERT_EQ(r.errors.size(), 1u) << errors(r);
    EXPECT_EQ(r.errors[0].loc.line, 20) << errors(r);
    EXPECT_GT(r.errors[0].loc.column, 0);
    EXPECT_EQ(r.errors[0].loc.field, "outputs.images[1].equal_to");
    EXPECT_NE(r.errors[0].message.find("is not another image"), std::string::npos) << errors(r);
  }
}

TEST(ParseImages, EqualToAnImageOfAnotherTexelFormatIsAnError) {
  const ParseResult r =
      parse("    - {name: a, from: hit}\n    - {name: b, from: color2, equal_to: a}\n");
  ASSERT_FALSE(r.value);
  EXPECT_NE(errors(r).find("different texel formats"), std::string::npos) << errors(r);
}

}  // namespace
}  // namespace rayspec
