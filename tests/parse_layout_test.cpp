// pipeline.layout: sets (descriptor set 0) or empty (no set, no push
// constant: R-EMPTY-LAYOUT), and what an empty layout cannot reach.
#include <gtest/gtest.h>

#include "parse/parse_case.h"
#include "parse_support.h"

namespace rayspec {
namespace {

ParseResult parseLayout(const std::string& layout, const std::string& more = "") {
  return parseCaseText(
      "rules: [R-EMPTY-LAYOUT]\n"
      "rays:\n"
      "  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]\n"
      "pipeline:\n"
      "  layout: " +
          layout +
          "\n"
          "  miss: [[count: miss, record: {hit: 0}]]\n"
          "outputs:\n"
          "  counters: [miss]\n"
          "  per_ray: [hit]\n" +
          more,
      "t.yaml", "t/t");
}

TEST(PipelineLayout, EmptyOrSets) {
  const ParseResult empty = parseLayout("empty");
  ASSERT_TRUE(empty.value) << firstError(empty);
  EXPECT_TRUE(empty.value->pipeline.empty_layout);
  const ParseResult sets = parseLayout("sets");
  ASSERT_TRUE(sets.value) << firstError(sets);
  EXPECT_FALSE(sets.value->pipeline.empty_layout);
}

TEST(PipelineLayout, ErrorsNameTheLineAndField) {
  const ParseResult bad = parseLayout("none");
  EXPECT_FALSE(bad.value);
  EXPECT_NE(firstError(bad).find("t.yaml:5"), std::string::npos) << firstError(bad);
  EXPECT_NE(firstError(bad).find("unknown layout 'none' (sets, empty)"), std::string::npos)
      << firstError(bad);
  // A storage image has no device address.
  const ParseResult image = parseLayout("empty", "  images: [{name: h, from: hit}]\n");
  EXPECT_FALSE(image.value);
  EXPECT_NE(firstError(image).find("t.yaml:5"), std::string::npos) << firstError(image);
  EXPECT_NE(firstError(image).find("pipeline.layout"), std::string::npos) << firstError(image);
  EXPECT_NE(firstError(image).find("outputs.images"), std::string::npos) << firstError(image);
  EXPECT_TRUE(parseLayout("sets", "  images: [{name: h, from: hit}]\n").value);
}

}  // namespace
}  // namespace rayspec
