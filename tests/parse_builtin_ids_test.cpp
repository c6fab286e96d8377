// The parser resolves a built-in once (program/builtins.h): every spelling
// of the table reads as its row's id and word, and a name no row reads is an
// error at its file:line:col.
#include <algorithm>
#include <string>
#include <vector>

#include "parse/parse_parts.h"
#include "parse/yaml_reader.h"
#include "parse_support.h"
#include "program/builtins.h"

namespace rayspec {
namespace {

Expr parsedExpr(const std::string& text, std::vector<Error>& errors) {
  YamlReader r("t.yaml", errors);
  Expr e;
  parseExpr(r, YAML::Load(text), "f", e);
  return e;
}

TEST(ParseBuiltinIds, EverySpellingOfTheTableReadsAsItsRow) {
  for (int i = 0; i < kBiCount; ++i) {
    const Builtin b = static_cast<Builtin>(i);
    std::vector<uint32_t> words{0};
    if (isWordFamily(b)) words = {0, 5};
    if (isSizedFamily(b)) words = {static_cast<uint32_t>(ValueType::Float16Vec3)};
    for (uint32_t word : words) {
      const std::string spelled = builtinSpelling(b, word);
      std::vector<Error> errors;
      const Expr e = parsedExpr(spelled, errors);
      EXPECT_TRUE(errors.empty()) << spelled << ": " << (errors.empty() ? "" : errors[0].format());
      EXPECT_EQ(e.kind, Expr::Kind::Builtin) << spelled;
      EXPECT_EQ(e.builtin, b) << spelled;
      EXPECT_EQ(e.word, word) << spelled;
      EXPECT_EQ(e.name, spelled);
    }
  }
}

// `record: [primitive_id]` records the built-in of the field's name: its id too.
TEST(ParseBuiltinIds, RecordShorthandReadsTheId) {
  const Case c = parsedCase(oneTriangleText("R-BUILTIN", "", ""));
  ASSERT_EQ(c.pipeline.hit_groups.size(), 1u);
  const Program& chit = *c.pipeline.hit_groups[0].closest_hit;
  ASSERT_EQ(chit.size(), 1u);
  ASSERT_EQ(chit[0].assigns.size(), 1u);
  EXPECT_TRUE(isBuiltin(chit[0].assigns[0].second, kBiHit));
}

// A name no row reads, and a family's own row name, are errors at the
// scalar's line and column, in the file's name.
TEST(ParseBuiltinIds, UnknownNameIsAnErrorAtItsFileLineAndColumn) {
  for (const char* name : {"primitive_idd", "payload.word<i>", "payload.word58"}) {
    std::string text = oneTriangleText("R-BUILTIN", "", "");
    const std::string from = "record: [hit]";
    const std::string to = std::string("record: {value: ") + name + "}";
    text.replace(text.find(from), from.size(), to);
    text.replace(text.find("per_ray: [hit]"), 14, "per_ray: [value]");
    const size_t at = text.find(name, text.find(to));
    const size_t line_start = text.rfind('\n', at) + 1;
    const auto line = std::count(text.begin(), text.begin() + static_cast<long>(at), '\n') + 1;
    const std::string where =
        "t.yaml:" + std::to_string(line) + ":" + std::to_string(at - line_start + 1) + ": ";
    const std::string error = firstError(parse(text));
    EXPECT_EQ(error.rfind(where, 0), 0u) << error << " (expected at " << where << ")";
    EXPECT_NE(error.find(std::string("unknown name '") + name + "'"), std::string::npos) << error;
  }
}

}  // namespace
}  // namespace rayspec
