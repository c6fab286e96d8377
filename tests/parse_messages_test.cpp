// The parser's messages: every problem as FILE:LINE:COL: field.path: what was
// expected, whatever shape the YAML has.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "parse/parse_case.h"
#include "parse_support.h"

namespace rayspec {
namespace {

ParseResult parseMessages(const std::string& text,
                          const std::vector<std::string>* catalog = nullptr,
                          const std::string& name = "family/m") {
  return parseCaseText(text, "m.yaml", name, catalog);
}

bool hasError(const ParseResult& r, int line, int column, const std::string& field,
              const std::string& text) {
  for (const Error& e : r.errors)
    if (e.loc.line == line && e.loc.column == column && e.loc.field == field &&
        e.message.find(text) != std::string::npos)
      return true;
  return false;
}

const char* kMinimal = R"(rules: [R-MASK]
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
pipeline:
  miss:
    - [count: miss]
outputs:
  counters: [miss]
)";

TEST(ParseMessages, DuplicateKeysAreErrorsWithLineColumnAndKeyPath) {
  ASSERT_TRUE(parseMessages(kMinimal).value) << allErrors(parseMessages(kMinimal));
  ParseResult r = parseMessages(std::string(kMinimal) +
                                "rays: {list: [{origin: [0, 0, 2], direction: [0, 0, -1]}]}\n");
  EXPECT_TRUE(hasError(r, 9, 1, "rays", "duplicate key 'rays' (first at line 2)")) << allErrors(r);
  EXPECT_FALSE(r.value);
  // Deeper: in a flow map of a list item, and in a block map.
  r = parseMessages(R"(rules: [R-MASK]
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1], origin: [1, 1, 1]}]
pipeline:
  miss: [[]]
  max_recursion: 1
  max_recursion: 2
)");
  EXPECT_TRUE(hasError(r, 3, 53, "rays.list[0].origin", "duplicate key 'origin'")) << allErrors(r);
  EXPECT_TRUE(hasError(r, 7, 3, "pipeline.max_recursion",
                       "duplicate key 'max_recursion' (first at line 6)"))
      << allErrors(r);
}

// A byte-order mark (or any byte a terminal does not show) inside the file is
// shown as \xNN where a message quotes it: the key looked like 'scene'.
TEST(ParseMessages, InvisibleBytesAreShownInMessages) {
  const ParseResult r =
      parseCaseText("rules: [R-IGNORE]\n\xEF\xBB\xBFscene: 12\n", "bom.yaml", "fam/bom");
  ASSERT_FALSE(r.errors.empty());
  EXPECT_NE(r.errors[0].format().find("unknown key '\\xEF\\xBB\\xBFscene'"), std::string::npos)
      << r.errors[0].format();
}

TEST(ParseMessages, UnknownRuleLabelsAreReportedAtTheLabel) {
  const std::string text = "rules: [R-MASK, R-NO-SUCH-RULE]\n" + std::string(kMinimal).substr(16);
  const std::vector<std::string> catalog = {"R-MASK", "R-UB"};
  ParseResult r = parseMessages(text, &catalog);
  EXPECT_TRUE(hasError(r, 1, 17, "rules[1]", "unknown rule label 'R-NO-SUCH-RULE'"))
      << allErrors(r);
  EXPECT_FALSE(r.value);
  EXPECT_TRUE(parseMessages(text).value) << "without a catalog only the label's form is checked";
  EXPECT_TRUE(parseMessages(kMinimal, &catalog).value);
}

TEST(ParseMessages, ImageAndCaseNamesMustBeFileNames) {
  auto with_image = [](const std::string& name) {
    std::string s = kMinimal;
    s += "  per_ray: [hit]\n  images: [{name: " + name + ", from: hit}]\n";
    s.replace(s.find("[count: miss]"), 13, "[count: miss, record: {hit: 0}]");
    return parseMessages(s);
  };
  EXPECT_TRUE(with_image("hit-map_2.v1").value) << allErrors(with_image("hit-map_2.v1"));
  for (const std::string& bad :
       {std::string("\"a/b\""), std::string("\"..\""), std::string("\".\""),
        std::string("\"sp ace\""), std::string("\"\""), std::string(101, 'x'),
        std::string("\"caf\xc3\xa9\"")}) {
    const ParseResult r = with_image(bad);
    EXPECT_FALSE(r.value) << bad;
    ASSERT_EQ(r.errors.size(), 1u) << allErrors(r);
    EXPECT_EQ(r.errors[0].loc.field, "outputs.images[0].name");
    EXPECT_EQ(r.errors[0].loc.line, 10) << allErrors(r);
    EXPECT_GT(r.errors[0].loc.column, 0);
  }
  EXPECT_TRUE(with_image(std::string(100, 'x')).value) << "100 bytes is the most";
  // A case's name names its results folder.
  ParseResult r = parseMessages(kMinimal, nullptr, "family/bad name");
  ASSERT_FALSE(r.errors.empty());
  EXPECT_EQ(r.errors[0].format().rfind(
                "m.yaml:1:1: case name: 'family/bad name' cannot name a results folder", 0),
            0u)
      << allErrors(r);
  EXPECT_FALSE(parseMessages(kMinimal, nullptr, "family/..").value);
  EXPECT_TRUE(parseMessages(kMinimal, nullptr, "family/fine-name_2").value);
}

TEST(ParseMessages, ANonScalarCounterNameIsAFieldErrorNotABadConversion) {
  std::string s = kMinimal;
  s.replace(s.find("counters: [miss]"), 16, "counters: [miss, {[a]: at_least}]");
  const ParseResult r = parseMessages(s);
  EXPECT_TRUE(hasError(r, 8, 21, "outputs.counters[1]", "expected a string")) << allErrors(r);
  EXPECT_EQ(allErrors(r).find("bad conversion"), std::string::npos) << allErrors(r);
}

// Every node of real case files replaced by values of every other shape: each
// problem still comes out as FILE:LINE:COL: field: message, never as a bare
// yaml-cpp exception ("bad conversion", "operator[] call on a scalar").
TEST(ParseMessages, YamlCppExceptionsComeOutWithFileLineColumnAndField) {
  const std::vector<std::string> shapes = {
      "{[a]: b}", "[[1, 2], {k: v}]", "{k: v}", "~", "\"text\"", "-1", ".nan",
      "[]",       "0x1FFFF",          "[{}]"};
  const std::string root = std::string(RAYSPEC_SOURCE_DIR) + "/cases/";
  size_t parses = 0;
  for (const char* file :
       {"builtins/closest-hit-and-miss.yaml", "intersection/sphere-both-roots.yaml",
        "sbt/shader-record-data.yaml", "callable/from-every-stage.yaml"}) {
    const YAML::Node original = YAML::LoadFile(root + file);
    // Every value node below the top, in pre-order.
    size_t count = 0;
    std::function<void(const YAML::Node&)> countNodes = [&](const YAML::Node& n) {
      for (auto it = n.begin(); it != n.end(); ++it) {
        const YAML::Node child = n.IsMap() ? it->second : *it;
        ++count;
        if (child.IsMap() || child.IsSequence()) countNodes(child);
      }
    };
    countNodes(original);
    ASSERT_GT(count, 20u) << file;
    for (size_t target = 0; target < count; ++target)
      for (const std::string& shape : shapes) {
        YAML::Node doc = YAML::Clone(original);
        size_t index = 0;
        std::function<bool(YAML::Node)> replace = [&](YAML::Node n) {
          for (auto it = n.begin(); it != n.end(); ++it) {
            YAML::Node child = n.IsMap() ? it->second : *it;
            if (index++ == target) {
              child = YAML::Load(shape);
              return true;
            }
            if ((child.IsMap() || child.IsSequence()) && replace(child)) return true;
          }
          return false;
        };
        ASSERT_TRUE(replace(doc));
        YAML::Emitter out;
        out << doc;
        const ParseResult r = parseCaseText(out.c_str(), file, "family/fuzz");
        ++parses;
        for (const Error& e : r.errors) {
          const std::string where = std::string(file) + " node " + std::to_string(target) +
                                    " := " + shape + ": " + e.format() + "\n" + out.c_str();
          EXPECT_GE(e.loc.line, 1) << where;
          EXPECT_GE(e.loc.column, 1) << where;
          EXPECT_FALSE(e.loc.field.empty()) << where;
          for (const char* leak :
               {"bad conversion", "yaml-cpp", "operator[]", "internal error", "bad file"})
            EXPECT_EQ(e.message.find(leak), std::string::npos) << where;
          if (::testing::Test::HasFailure()) return;
        }
      }
  }
  EXPECT_GT(parses, 1000u);
}

}  // namespace
}  // namespace rayspec
