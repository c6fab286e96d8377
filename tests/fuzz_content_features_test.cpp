// fuzz/content_features.h: the features a case's text shows, which the
// known bug classes key on, read from the parsed case.
#include <gtest/gtest.h>

#include "fuzz/content_features.h"
#include "fuzz/generate_case.h"
#include "parse/parse_case.h"

namespace rayspec {
namespace {

// A generated case's features of these names are what its text shows (the
// generator reads them from its text: one definition), so a generated case
// and the same text saved and judged elsewhere fall in the same known class;
// the generator draws each now and then. 200 cases: about 1 s.
TEST(ContentFeatures, AgreeWithWhatTheGeneratorDrew) {
  std::map<std::string, size_t> seen;
  for (uint64_t seed = 0; seed < 200; ++seed) {
    const GeneratedCase g = generateCase(seed);
    const ParseResult p = parseCaseText(g.yaml, g.name + ".yaml", g.name);
    ASSERT_TRUE(p.value) << g.name;
    std::set<std::string> drawn;
    for (const std::string& f : contentFeatureNames())
      if (g.features.count(f)) drawn.insert(f);
    const std::set<std::string> shown = contentFeatures(*p.value);
    EXPECT_EQ(shown, drawn) << g.name;
    EXPECT_EQ(contentFeatures(g.yaml), shown) << g.name;
    for (const std::string& f : shown) ++seen[f];
  }
  for (const std::string& f : contentFeatureNames()) EXPECT_GE(seen[f], 3u) << f;
}

// Each feature from a text no generator made.
TEST(ContentFeatures, ReadFromAHandWrittenCase) {
  const std::string text = R"(rules: [R-INACTIVE]
scene:
  build: {first_vertex: 2}
  blas:
    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [.nan, 0, 1], [1, 1, 1], [0, 1, 1]]}}]
    b: [{aabbs: [[.nan, 0, 0, 1, 1, 1], [0, 0, 2, 1, 1, 3]]}]
  instances: [{blas: t}, {blas: null}, {blas: b}]
rays:
  list: [{origin: [0.2, 0.2, 5], direction: [0, 0, -1]}]
pipeline:
  max_recursion: 2
  miss: [[{record: {hit: 0, color: {vec4: [{x: world_ray_direction}, 0.0, 0.0, 1.0]}}}]]
  hit_groups:
    - closest_hit: [{trace: {origin: world_ray_origin, direction: [0, 0, -1]}}, {record: {value: primitive_id}}]
    - {}
  callables:
    - [{struct: {name: s, members: {a: int16, b: uint}}}, {set: {s.a: {int16: call.value}}}, {call_data: {value: {uint: var.s.a}}}]
outputs:
  per_ray: [hit, value, color]
)";
  const std::set<std::string> all(contentFeatureNames().begin(), contentFeatureNames().end());
  EXPECT_EQ(contentFeatures(text), all);
  // A NaN in Y leaves a triangle active; the record before the trace reads the hit's own.
  std::string other = text;
  other.replace(other.find("[.nan, 0, 1]"), 12, "[0, .nan, 1]");
  const std::string before =
      "[{record: {value: primitive_id}}, {trace: {origin: world_ray_origin, "
      "direction: [0, 0, -1]}}]";
  other.replace(other.find("[{trace:"), before.size(), before);
  EXPECT_EQ(contentFeatures(other).count("nan-vertex"), 0u);
  EXPECT_EQ(contentFeatures(other).count("hit-builtin-after-trace"), 0u);
  // A miss that reads no world ray beside the group without shaders.
  std::string plain = text;
  plain.replace(plain.find("{x: world_ray_direction}"), 24, "0.5");
  EXPECT_EQ(contentFeatures(plain).count("miss-world-ray-beside-empty-group"), 0u);
  EXPECT_EQ(contentFeatures(plain).size(), all.size() - 1);
  // A struct of a uint alone holds no sized value; a sized local without a struct.
  std::string uints = text;
  uints.replace(uints.find("a: int16"), 8, "a: uint");
  uints.replace(uints.find("{int16: call.value}"), 19, "call.value");
  uints.replace(uints.find("{uint: var.s.a}"), 15, "var.s.a");
  EXPECT_EQ(contentFeatures(uints).count("sized-values"), 0u);
  EXPECT_EQ(contentFeatures(uints).count("struct-local"), 1u);
  std::string local = text;
  const std::string declared = "{struct: {name: s, members: {a: int16, b: uint}}}, {set: {s.a: ";
  local.replace(local.find(declared), declared.size(), "{let: {s: ");
  local.replace(local.find("var.s.a"), 7, "var.s");
  EXPECT_EQ(contentFeatures(local).count("sized-values"), 1u);
  EXPECT_EQ(contentFeatures(local).count("struct-local"), 0u);
  EXPECT_TRUE(contentFeatures("not: [a case").empty());
}

}  // namespace
}  // namespace rayspec
